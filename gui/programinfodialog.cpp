#include "programinfodialog.h"

#include "runpanel.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace frezka::gui {

namespace {

constexpr char kAxes[] = "XYZ";

QTableWidget *table(int columns, const char *name, QWidget *parent)
{
    auto *t = new QTableWidget(0, columns, parent);
    t->setObjectName(QLatin1String(name));
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->verticalHeader()->hide();
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    return t;
}

QString mm(double v)
{
    return QString::number(v, 'f', 3);
}

} // namespace

ProgramInfoDialog::ProgramInfoDialog(QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("programInfoDialog"));
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("programInfoSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_extentTitle = new QLabel(this);
    m_extent = table(5, "programInfoExtent", this);
    m_toolsTitle = new QLabel(this);
    m_tools = table(4, "programInfoTools", this);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_extentTitle);
    layout->addWidget(m_extent);
    layout->addWidget(m_toolsTitle);
    layout->addWidget(m_tools, 1);
    layout->addWidget(buttons);
    resize(560, 480);
    retranslate();
}

void ProgramInfoDialog::setInfo(const session::ProgramInfo &info, const QString &fileName)
{
    m_info = info;
    m_fileName = fileName;
    fill();
}

QString ProgramInfoDialog::summary() const
{
    return m_summary->text();
}

void ProgramInfoDialog::fill()
{
    const QString time =
        m_info.estimatedS < 0 ? tr("not planned") : RunPanel::formatDuration(m_info.estimatedS);
    m_summary->setText(tr("%1: %2 lines, %3 bytes, %4 moves, %5 mm of path, estimated time %6.")
                           .arg(m_fileName)
                           .arg(m_info.lines)
                           .arg(m_info.bytes)
                           .arg(m_info.motions)
                           .arg(m_info.lengthMm, 0, 'f', 1)
                           .arg(time));
    m_extent->setRowCount(m_info.moves ? 3 : 0);
    for (int a = 0; a < (m_info.moves ? 3 : 0); ++a) {
        const auto i = std::size_t(a);
        const QString cells[] = {QString(QLatin1Char(kAxes[a])), mm(m_info.workMinMm[i]),
                                 mm(m_info.workMaxMm[i]), mm(m_info.machineMinMm[i]),
                                 mm(m_info.machineMaxMm[i])};
        for (int c = 0; c < 5; ++c)
            m_extent->setItem(a, c, new QTableWidgetItem(cells[c]));
    }
    m_tools->setRowCount(int(m_info.tools.size()));
    for (int r = 0; r < int(m_info.tools.size()); ++r) {
        const session::ToolShare &t = m_info.tools[std::size_t(r)];
        const QString cells[] = {
            t.tool < 0 ? tr("in the spindle") : QStringLiteral("T%1").arg(t.tool),
            QString::number(t.fromLine),
            t.seconds < 0 ? tr("not planned") : RunPanel::formatDuration(t.seconds),
            QString::number(t.cutLengthMm, 'f', 1)};
        for (int c = 0; c < 4; ++c)
            m_tools->setItem(r, c, new QTableWidgetItem(cells[c]));
    }
}

void ProgramInfoDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ProgramInfoDialog::retranslate()
{
    setWindowTitle(tr("Program info"));
    m_extentTitle->setText(tr("Extent (mm)"));
    m_extent->setHorizontalHeaderLabels(
        {tr("Axis"), tr("Program min"), tr("Program max"), tr("Machine min"), tr("Machine max")});
    m_toolsTitle->setText(tr("Tools in their order"));
    m_tools->setHorizontalHeaderLabels(
        {tr("Tool"), tr("From line"), tr("Planned time"), tr("Cut length (mm)")});
    fill();
}

} // namespace frezka::gui
