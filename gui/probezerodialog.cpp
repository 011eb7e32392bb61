#include "probezerodialog.h"

#include "probesetuppicture.h"

#include "session/heightprobe.h"
#include "session/machinelink.h"
#include "session/workoffsets.h"

#include <QCloseEvent>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace frezka::gui {

namespace {

QDoubleSpinBox *spin(QWidget *parent, const char *name, double lo, double hi, double value,
                     int decimals = 3)
{
    auto *s = new QDoubleSpinBox(parent);
    s->setObjectName(QLatin1String(name));
    s->setRange(lo, hi);
    s->setDecimals(decimals);
    s->setValue(value);
    return s;
}

} // namespace

ProbeZeroDialog::ProbeZeroDialog(session::MachineLink &link, const machine::MachineConfig &config,
                                 session::WorkOffsets &offsets, QWidget *parent)
    : QDialog(parent)
    , m_link(link)
    , m_config(config)
    , m_offsets(offsets)
    , m_probe(new session::HeightProbe(link, config, this))
    , m_picture(new ProbeSetupPicture(this))
    , m_kind(new QComboBox(this))
    , m_xDirection(new QComboBox(this))
    , m_yDirection(new QComboBox(this))
    , m_plate(spin(this, "plate", 0, 100, 1.5))
    , m_diameter(spin(this, "toolDiameter", 0, 100, 6))
    , m_travel(spin(this, "travel", 0.1, 200, 10))
    , m_reach(spin(this, "reach", 0, 200, 15))
    , m_feed(spin(this, "probeFeed", 1, 5000, 100, 0))
    , m_retract(spin(this, "retract", 0.1, 20, 1))
    , m_steps(new QLabel(this))
    , m_status(new QLabel(this))
    , m_error(new QLabel(this))
    , m_kindLabel(new QLabel(this))
    , m_xLabel(new QLabel(this))
    , m_yLabel(new QLabel(this))
    , m_plateLabel(new QLabel(this))
    , m_diameterLabel(new QLabel(this))
    , m_travelLabel(new QLabel(this))
    , m_reachLabel(new QLabel(this))
    , m_feedLabel(new QLabel(this))
    , m_retractLabel(new QLabel(this))
    , m_probeButton(new QPushButton(this))
    , m_close(new QPushButton(this))
{
    setObjectName(QStringLiteral("probeZeroDialog"));
    m_kind->setObjectName(QStringLiteral("probeKind"));
    m_xDirection->setObjectName(QStringLiteral("xDirection"));
    m_yDirection->setObjectName(QStringLiteral("yDirection"));
    m_probeButton->setObjectName(QStringLiteral("probe"));
    m_status->setObjectName(QStringLiteral("probeStatus"));
    m_error->setObjectName(QStringLiteral("probeError"));
    m_steps->setObjectName(QStringLiteral("probeSteps"));
    for (QLabel *l : {m_steps, m_status, m_error})
        l->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #b00020"));
    m_error->hide();
    for (int i = 0; i < 5; ++i)
        m_kind->addItem(QString());
    for (QComboBox *c : {m_xDirection, m_yDirection})
        c->addItems({QStringLiteral("+"), QStringLiteral("-")});
    auto *form = new QFormLayout;
    form->addRow(m_kindLabel, m_kind);
    form->addRow(m_xLabel, m_xDirection);
    form->addRow(m_yLabel, m_yDirection);
    form->addRow(m_plateLabel, m_plate);
    form->addRow(m_diameterLabel, m_diameter);
    form->addRow(m_travelLabel, m_travel);
    form->addRow(m_reachLabel, m_reach);
    form->addRow(m_feedLabel, m_feed);
    form->addRow(m_retractLabel, m_retract);
    auto *top = new QHBoxLayout;
    top->addLayout(form);
    top->addWidget(m_picture, 1);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch();
    buttons->addWidget(m_probeButton);
    buttons->addWidget(m_close);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_steps);
    layout->addWidget(m_status);
    layout->addWidget(m_error);
    layout->addLayout(buttons);
    connect(m_kind, &QComboBox::currentIndexChanged, this, &ProbeZeroDialog::updateSetup);
    connect(m_xDirection, &QComboBox::currentIndexChanged, this, &ProbeZeroDialog::updateSetup);
    connect(m_yDirection, &QComboBox::currentIndexChanged, this, &ProbeZeroDialog::updateSetup);
    connect(m_probeButton, &QPushButton::clicked, this, &ProbeZeroDialog::probe);
    connect(m_close, &QPushButton::clicked, this, &QDialog::close);
    connect(m_probe, &session::HeightProbe::finished, this, &ProbeZeroDialog::onFinished);
    retranslate();
    updateSetup();
}

void ProbeZeroDialog::setKind(Kind kind)
{
    m_kind->setCurrentIndex(kind);
}

ProbeZeroDialog::Kind ProbeZeroDialog::kind() const
{
    return static_cast<Kind>(m_kind->currentIndex());
}

bool ProbeZeroDialog::isProbing() const
{
    return m_probe->running();
}

QString ProbeZeroDialog::statusText() const
{
    return m_status->text();
}

QString ProbeZeroDialog::errorText() const
{
    return m_error->isHidden() ? QString() : m_error->text();
}

void ProbeZeroDialog::showError(const QString &text)
{
    m_error->setText(text);
    m_error->setVisible(!text.isEmpty());
}

// The fields of the kind chosen, its picture and its steps.
void ProbeZeroDialog::updateSetup()
{
    const Kind k = kind();
    const bool plate = k == ZPlate, corner = k == OutsideCorner || k == InsideCorner;
    const bool x = k == XEdge || corner, y = k == YEdge || corner;
    const std::pair<QWidget *, bool> shown[] = {{m_xDirection, x},
                                                {m_xLabel, x},
                                                {m_yDirection, y},
                                                {m_yLabel, y},
                                                {m_plate, plate},
                                                {m_plateLabel, plate},
                                                {m_diameter, !plate},
                                                {m_diameterLabel, !plate},
                                                {m_reach, k == OutsideCorner},
                                                {m_reachLabel, k == OutsideCorner}};
    for (const auto &[w, on] : shown)
        w->setVisible(on);
    const int dx = m_xDirection->currentIndex() == 0 ? 1 : -1;
    const int dy = m_yDirection->currentIndex() == 0 ? 1 : -1;
    m_picture->setSetup(static_cast<ProbeSetupPicture::Kind>(k), dx, dy);
    switch (k) {
    case ZPlate:
        m_steps->setText(tr("1. Lay the plate on the work and connect the probe's clip to the "
                            "tool.\n2. Jog the tool over the plate, a few mm above it.\n3. Press "
                            "Probe: the tool goes down until it touches (fast, then slow) and "
                            "backs off; the work's top becomes Z 0."));
        break;
    case XEdge:
    case YEdge:
        m_steps->setText(tr("1. Jog the tool beside the edge, below the work's top, within the "
                            "travel of it.\n2. Choose the direction toward the edge and the "
                            "tool's diameter.\n3. Press Probe: the tool moves until it touches "
                            "and comes back; the edge becomes 0 on that axis."));
        break;
    case OutsideCorner:
        m_steps->setText(tr("1. Jog the tool off the corner diagonally, below the work's top.\n"
                            "2. Set the reach: how far to move beside each face (more than the "
                            "distance to the corner plus the tool's radius).\n3. Press Probe: X "
                            "first, then Y; the corner becomes X 0 Y 0."));
        break;
    case InsideCorner:
        m_steps->setText(tr("1. Jog the tool into the pocket near its corner, below the top.\n"
                            "2. Choose the directions toward the two walls.\n3. Press Probe: X "
                            "first, then Y, both from where the tool stands; the corner becomes "
                            "X 0 Y 0."));
        break;
    }
}

bool ProbeZeroDialog::probe()
{
    if (isProbing()) {
        m_probe->cancel();
        return false;
    }
    showError({});
    m_trips.clear();
    const Kind k = kind();
    m_axes = k == ZPlate  ? std::vector<int>{2}
             : k == XEdge ? std::vector<int>{0}
             : k == YEdge ? std::vector<int>{1}
                          : std::vector<int>{0, 1};
    if (!startAxis(m_axes.front())) {
        showError(m_probe->error());
        return false;
    }
    m_status->setText(tr("Probing…"));
    m_probeButton->setText(tr("S&top"));
    return true;
}

bool ProbeZeroDialog::startAxis(int axis)
{
    session::HeightProbeSettings s;
    s.feedMmPerMin = m_feed->value();
    s.slowFeedMmPerMin = m_feed->value() / 5;
    s.retractMm = m_retract->value();
    if (axis == 2) { // the plate under the tool
        const auto &at = m_link.state().positionMm;
        s.clearanceZMm = at[2];
        s.bottomZMm = at[2] - m_travel->value();
        return m_probe->startAt(at[0], at[1], s);
    }
    s.travelMm = m_travel->value();
    const int dx = m_xDirection->currentIndex() == 0 ? 1 : -1;
    const int dy = m_yDirection->currentIndex() == 0 ? 1 : -1;
    if (kind() == OutsideCorner) // toward the other probe's side, beside this face
        s.reachMm = (axis == 0 ? dy : dx) * m_reach->value();
    return m_probe->startEdge(axis, axis == 0 ? dx : dy, s);
}

void ProbeZeroDialog::onFinished(bool ok)
{
    if (ok && m_probe->pointZMm()) {
        m_trips.push_back(*m_probe->pointZMm());
        if (m_trips.size() < m_axes.size()) {
            if (startAxis(m_axes[m_trips.size()]))
                return;
            ok = false;
        } else {
            apply();
        }
    }
    m_probeButton->setText(tr("&Probe"));
    if (!ok) {
        m_status->setText(tr("Nothing was set."));
        showError(m_probe->error());
    }
    emit probingFinished(ok);
}

// The trips into the active work system: Z from the plate, X / Y from the edges.
void ProbeZeroDialog::apply()
{
    session::OffsetState next = m_offsets.state();
    const int dx = m_xDirection->currentIndex() == 0 ? 1 : -1;
    const int dy = m_yDirection->currentIndex() == 0 ? 1 : -1;
    for (std::size_t k = 0; k < m_trips.size(); ++k) {
        const int axis = m_axes[k];
        next = axis == 2 ? session::touchPlateZero(next, m_trips[k], m_plate->value())
                         : session::edgeZero(next, axis, axis == 0 ? dx : dy, m_trips[k],
                                             m_diameter->value());
    }
    const auto active = static_cast<std::size_t>(next.active);
    m_offsets.setSystem(next.active, next.systems[active]);
    const session::Axes4 &v = next.systems[active];
    m_status->setText(tr("%1 is now X %2, Y %3, Z %4 (machine mm of its zero).")
                          .arg(session::workSystemName(next.active))
                          .arg(v[0], 0, 'f', 3)
                          .arg(v[1], 0, 'f', 3)
                          .arg(v[2], 0, 'f', 3));
}

void ProbeZeroDialog::closeEvent(QCloseEvent *event)
{
    if (isProbing()) { // the tool comes back first
        m_probe->cancel();
        m_status->setText(tr("Probing stopped: the tool goes back to where it started. Close "
                             "the dialog when it is there."));
        event->ignore();
        return;
    }
    QDialog::closeEvent(event);
}

void ProbeZeroDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ProbeZeroDialog::retranslate()
{
    setWindowTitle(tr("Probe work zero"));
    const QString kinds[] = {tr("Z from a touch plate"), tr("X from an edge"), tr("Y from an edge"),
                             tr("X and Y from an outside corner"),
                             tr("X and Y from an inside corner")};
    for (int i = 0; i < 5; ++i)
        m_kind->setItemText(i, kinds[i]);
    m_kindLabel->setText(tr("What to probe"));
    m_xLabel->setText(tr("X direction toward the work"));
    m_yLabel->setText(tr("Y direction toward the work"));
    m_plateLabel->setText(tr("Plate thickness (mm)"));
    m_diameterLabel->setText(tr("Tool diameter (mm)"));
    m_travelLabel->setText(tr("Travel at most (mm)"));
    m_reachLabel->setText(tr("Reach beside each face (mm)"));
    m_feedLabel->setText(tr("Probing feed (mm/min)"));
    m_retractLabel->setText(tr("Back-off before the slow probe (mm)"));
    m_probeButton->setText(isProbing() ? tr("S&top") : tr("&Probe"));
    m_close->setText(tr("&Close"));
    updateSetup();
}

} // namespace frezka::gui
