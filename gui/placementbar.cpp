#include "placementbar.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace frezka::gui {

namespace {
constexpr char kAxes[] = "XYZA";
} // namespace

PlacementBar::PlacementBar(QWidget *parent)
    : QFrame(parent)
{
    setObjectName(QStringLiteral("placementBar"));
    setFrameShape(QFrame::StyledPanel);
    setStyleSheet(QStringLiteral("#placementBar { background: #fff4d6; }"));
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("placementText"));
    m_text->setWordWrap(true);
    m_anchorLabel = new QLabel(this);
    m_anchor = new QComboBox(this);
    m_anchor->setObjectName(QStringLiteral("placementAnchor"));
    for (int i = 0; i < 6; ++i)
        m_anchor->addItem(QString(), i);
    m_anchor->setFocusPolicy(Qt::NoFocus);
    connect(m_anchor, &QComboBox::currentIndexChanged, this, &PlacementBar::refresh);
    m_here = new QPushButton(this);
    m_here->setObjectName(QStringLiteral("placeHere"));
    m_here->setFocusPolicy(Qt::NoFocus); // it changes the work offset: never through the focus
    connect(m_here, &QPushButton::clicked, this, [this] {
        emit workOffsetRequested(session::stockZeroOffset(m_fit, m_offsets, m_machineMm, anchor()));
    });
    m_fitButton = new QPushButton(this);
    m_fitButton->setObjectName(QStringLiteral("placeFit"));
    m_fitButton->setFocusPolicy(Qt::NoFocus);
    connect(m_fitButton, &QPushButton::clicked, this, [this] {
        session::Axes4 offset = m_offsets.systems[std::size_t(m_offsets.active)];
        for (std::size_t a = 0; a < 4; ++a)
            offset[a] += m_fit.shiftMm[a];
        emit workOffsetRequested(offset);
    });
    m_preview = new QLabel(this);
    m_preview->setObjectName(QStringLiteral("placementPreview"));
    m_preview->setWordWrap(true);
    auto *row = new QHBoxLayout;
    row->addWidget(m_anchorLabel);
    row->addWidget(m_anchor);
    row->addWidget(m_here);
    row->addStretch();
    row->addWidget(m_fitButton);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_text);
    layout->addLayout(row);
    layout->addWidget(m_preview);
    retranslate();
    hide();
}

void PlacementBar::setProgram(const session::TravelFit &fit, const session::OffsetState &offsets,
                              const machine::MachineConfig &config)
{
    m_fit = fit;
    m_offsets = offsets;
    m_config = config;
    setVisible(fit.moves && !fit.inside());
    refresh();
}

void PlacementBar::setPosition(const session::Axes4 &machineMm, bool canSet)
{
    if (machineMm == m_machineMm && canSet == m_canSet)
        return;
    m_machineMm = machineMm;
    m_canSet = canSet;
    if (isVisible())
        refresh();
}

session::StockAnchor PlacementBar::anchor() const
{
    return session::StockAnchor(m_anchor->currentData().toInt());
}

void PlacementBar::setAnchor(session::StockAnchor anchor)
{
    m_anchor->setCurrentIndex(m_anchor->findData(int(anchor)));
}

QString PlacementBar::text() const
{
    return m_text->text() + QLatin1Char('\n') + m_preview->text();
}

session::Placement PlacementBar::preview() const
{
    return session::placeProgram(m_fit, m_offsets,
                                 session::stockZeroOffset(m_fit, m_offsets, m_machineMm, anchor()),
                                 m_config);
}

// Which axis leaves the travel on which side, from which line, and how far at most.
QString PlacementBar::excursionsText() const
{
    QStringList lines;
    for (const session::TravelExcursion &e : m_fit.excursions) {
        lines << tr("%1 goes to %2 mm at line %3, %4 mm beyond the travel's %5 mm.")
                     .arg(QLatin1Char(kAxes[e.axis]))
                     .arg(e.farthestValueMm, 0, 'f', 3)
                     .arg(e.firstLine)
                     .arg(e.farthestBeyondMm, 0, 'f', 3)
                     .arg(e.limitMm, 0, 'f', 3);
    }
    return lines.join(QLatin1Char(' '));
}

void PlacementBar::refresh()
{
    m_text->setText(
        tr("The program leaves the machine's travel at the current work zero. %1 Its "
           "coordinates are probably relative to the stock: bring the tool to the chosen point "
           "of the stock, its tip on the stock's top (the program's Z0), and set the work zero "
           "there.")
            .arg(excursionsText()));
    const session::Placement p = preview();
    QStringList extent;
    for (int a = 0; a < 3; ++a) {
        if (m_config.axes[std::size_t(a)].present)
            extent << QStringLiteral("%1 %2 … %3")
                          .arg(QLatin1Char(kAxes[a]))
                          .arg(p.minMm[std::size_t(a)], 0, 'f', 3)
                          .arg(p.maxMm[std::size_t(a)], 0, 'f', 3);
    }
    m_preview->setText(
        (p.inside ? tr("With the work zero set here the program would sit at %1 mm: inside the "
                       "travel.")
                  : tr("With the work zero set here the program would sit at %1 mm: still "
                       "outside the travel. Move to the stock first or choose another point."))
            .arg(extent.join(QStringLiteral(", "))));
    m_preview->setStyleSheet(p.inside ? QStringLiteral("color: #1a7f1a; font-weight: bold;")
                                      : QStringLiteral("color: #c00; font-weight: bold;"));
    m_here->setEnabled(m_canSet);
    m_fitButton->setEnabled(m_canSet && m_fit.fitsElsewhere);
    m_fitButton->setVisible(m_fit.fitsElsewhere);
}

void PlacementBar::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QFrame::changeEvent(event);
}

void PlacementBar::retranslate()
{
    m_anchorLabel->setText(tr("Here is the stock's:"));
    const QString anchors[] = {tr("program's X0 Y0"),    tr("front left corner"),
                               tr("front right corner"), tr("back left corner"),
                               tr("back right corner"),  tr("centre")};
    for (int i = 0; i < 6; ++i)
        m_anchor->setItemText(i, anchors[i]);
    m_here->setText(tr("Set the work zero here"));
    m_here->setToolTip(tr("Sets the active work offset so that the chosen point of the program "
                          "is at the current X/Y and the program's Z0 at the current Z"));
    m_fitButton->setText(tr("Shift into the travel"));
    m_fitButton->setToolTip(tr("Shifts the active work offset by the least that puts the whole "
                               "program inside the soft limits (as frezka-cli check suggests)"));
    refresh();
}

} // namespace frezka::gui
