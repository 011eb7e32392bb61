#include "tooltabledialog.h"

#include "session/heightprobe.h"
#include "session/toollength.h"

#include <QCloseEvent>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace frezka::gui {

namespace {

QString number(double v)
{
    return QString::number(v, 'g', 12);
}

// A number as typed: the C locale's point or the user's decimal separator.
bool readNumber(const QString &text, double *value)
{
    bool ok = false;
    const QString t = text.trimmed();
    *value = t.isEmpty() ? 0.0 : t.toDouble(&ok);
    if (!ok && !t.isEmpty())
        *value = QLocale().toDouble(t, &ok);
    return (ok || t.isEmpty()) && std::isfinite(*value);
}

} // namespace

ToolTableDialog::ToolTableDialog(const QString &path, QWidget *parent)
    : QDialog(parent)
    , m_path(path)
    , m_grid(new QTableWidget(0, 5, this))
    , m_file(new QLabel(this))
    , m_error(new QLabel(this))
    , m_add(new QPushButton(this))
    , m_remove(new QPushButton(this))
    , m_save(new QPushButton(this))
    , m_close(new QPushButton(this))
    , m_measure(new QPushButton(this))
    , m_status(new QLabel(this))
{
    setObjectName(QStringLiteral("toolTableDialog"));
    m_grid->setObjectName(QStringLiteral("toolGrid"));
    m_error->setObjectName(QStringLiteral("toolTableError"));
    m_add->setObjectName(QStringLiteral("addTool"));
    m_remove->setObjectName(QStringLiteral("removeTool"));
    m_save->setObjectName(QStringLiteral("saveToolTable"));
    m_close->setObjectName(QStringLiteral("closeToolTable"));
    m_measure->setObjectName(QStringLiteral("measureTool"));
    m_status->setObjectName(QStringLiteral("toolTableStatus"));
    m_status->setWordWrap(true);
    m_status->hide();
    m_measure->hide(); // until a machine with a tool sensor is given
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #b00020"));
    m_error->hide();
    m_file->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_grid->horizontalHeader()->setStretchLastSection(true);
    m_grid->setSelectionBehavior(QAbstractItemView::SelectRows);
    auto *buttons = new QHBoxLayout;
    for (QPushButton *b : {m_add, m_remove, m_measure})
        buttons->addWidget(b);
    buttons->addStretch();
    for (QPushButton *b : {m_save, m_close})
        buttons->addWidget(b);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_file);
    layout->addWidget(m_grid);
    layout->addWidget(m_status);
    layout->addWidget(m_error);
    layout->addLayout(buttons);
    connect(m_add, &QPushButton::clicked, this, &ToolTableDialog::addTool);
    connect(m_remove, &QPushButton::clicked, this, &ToolTableDialog::removeSelectedTool);
    connect(m_save, &QPushButton::clicked, this, &ToolTableDialog::save);
    connect(m_close, &QPushButton::clicked, this, &QDialog::close);
    connect(m_measure, &QPushButton::clicked, this, &ToolTableDialog::measureSelectedTool);
    retranslate();
    resize(640, 400);
    reload();
}

QString ToolTableDialog::errorText() const
{
    return m_error->isHidden() ? QString() : m_error->text();
}

void ToolTableDialog::showError(const QString &text)
{
    m_error->setText(text);
    m_error->setVisible(!text.isEmpty());
}

bool ToolTableDialog::reload()
{
    gcode::ToolTable table;
    gcode::Error error;
    if (!gcode::readToolTableFile(m_path.toStdString(), &table, &error)) {
        showError(gcode::formatError(m_path, error));
        return false;
    }
    m_rows = table.tools;
    m_grid->setRowCount(0);
    m_grid->setRowCount(int(m_rows.size()));
    for (int r = 0; r < int(m_rows.size()); ++r)
        setRow(r, m_rows[std::size_t(r)]);
    showError({});
    return true;
}

void ToolTableDialog::setRow(int row, const gcode::ToolEntry &e)
{
    const QString texts[] = {QString::number(e.tool), QString::number(e.pocket),
                             number(e.offsetMm[2]), number(e.diameterMm),
                             QString::fromStdString(e.comment)};
    for (int c = 0; c < 5; ++c)
        m_grid->setItem(row, c, new QTableWidgetItem(texts[c]));
}

void ToolTableDialog::addTool()
{
    int next = 1;
    for (int r = 0; r < m_grid->rowCount(); ++r) {
        const QTableWidgetItem *it = m_grid->item(r, ToolColumn);
        next = std::max(next, (it ? it->text().toInt() : 0) + 1);
    }
    gcode::ToolEntry e;
    e.tool = e.pocket = next;
    const int row = m_grid->rowCount();
    m_grid->insertRow(row);
    m_rows.push_back(e);
    setRow(row, e);
    m_grid->setCurrentCell(row, LengthColumn);
}

void ToolTableDialog::removeSelectedTool()
{
    const int row = m_grid->currentRow();
    if (row < 0 || row >= m_grid->rowCount())
        return;
    m_grid->removeRow(row);
    m_rows.erase(m_rows.begin() + row);
}

bool ToolTableDialog::tableFromGrid(gcode::ToolTable *table, QString *error) const
{
    gcode::ToolTable out;
    for (int r = 0; r < m_grid->rowCount(); ++r) {
        gcode::ToolEntry e = m_rows[std::size_t(r)];
        auto text = [&](int c) {
            const QTableWidgetItem *it = m_grid->item(r, c);
            return it ? it->text().trimmed() : QString();
        };
        bool ok = false;
        e.tool = text(ToolColumn).toInt(&ok);
        if (!ok || e.tool < 1) {
            *error = tr("Row %1: the tool number must be a whole number from 1 up.").arg(r + 1);
            return false;
        }
        if (out.find(e.tool)) {
            *error = tr("Row %1: tool %2 is listed twice; give it another number or remove "
                        "the row.")
                         .arg(r + 1)
                         .arg(e.tool);
            return false;
        }
        e.pocket = text(PocketColumn).isEmpty() ? e.tool : text(PocketColumn).toInt(&ok);
        if (!ok || e.pocket < 0) {
            *error = tr("Row %1: the pocket must be a whole number from 0 up.").arg(r + 1);
            return false;
        }
        if (!readNumber(text(LengthColumn), &e.offsetMm[2])) {
            *error = tr("Row %1: the length must be a number of mm, e.g. 42.5.").arg(r + 1);
            return false;
        }
        if (!readNumber(text(DiameterColumn), &e.diameterMm) || e.diameterMm < 0) {
            *error = tr("Row %1: the diameter must be a number of mm, 0 or more.").arg(r + 1);
            return false;
        }
        e.comment = text(CommentColumn).toStdString();
        if (e.comment.find_first_of("\n\r") != std::string::npos)
            e.comment = text(CommentColumn).simplified().toStdString();
        out.tools.push_back(std::move(e));
    }
    *table = std::move(out);
    return true;
}

bool ToolTableDialog::save()
{
    gcode::ToolTable table;
    QString why;
    if (!tableFromGrid(&table, &why)) {
        showError(why);
        return false;
    }
    gcode::Error error;
    if (!gcode::writeToolTableFile(m_path.toStdString(), table, &error)) {
        showError(gcode::translatedMessage(error));
        return false;
    }
    m_rows = table.tools;
    showError({});
    emit saved(table);
    return true;
}

void ToolTableDialog::setToolSensor(session::MachineLink &link,
                                    const machine::MachineConfig &config)
{
    delete m_probe;
    m_probe = new session::HeightProbe(link, config, this);
    connect(m_probe, &session::HeightProbe::finished, this, &ToolTableDialog::measureFinished);
    m_sensor = config.tools.sensor;
    m_measure->setVisible(session::toolSensorProblem(config).isEmpty());
    updateMeasureButton();
}

bool ToolTableDialog::measuring() const
{
    return m_probe && m_probe->running();
}

bool ToolTableDialog::measureSelectedTool()
{
    if (measuring()) {
        m_probe->cancel();
        return false;
    }
    const int row = m_grid->currentRow();
    const QTableWidgetItem *it = row >= 0 ? m_grid->item(row, ToolColumn) : nullptr;
    bool ok = false;
    const int tool = it ? it->text().toInt(&ok) : 0;
    if (!m_probe || !ok || tool < 1) {
        showError(tr("Select the row of the tool in the spindle, then measure it."));
        return false;
    }
    if (!m_probe->startAt(m_sensor.xMm, m_sensor.yMm, session::toolSensorSettings(m_sensor))) {
        showError(m_probe->error());
        return false;
    }
    m_measuringRow = row;
    m_measuringTool = tool;
    showError({});
    m_status->setText(tr("Measuring tool %1 on the tool sensor…").arg(tool));
    m_status->show();
    updateMeasureButton();
    return true;
}

// The length into the measured row (if it still shows that tool), then saved.
void ToolTableDialog::measureFinished(bool ok)
{
    updateMeasureButton();
    const std::optional<double> trip = m_probe->pointZMm();
    if (!ok || !trip) {
        m_status->hide();
        showError(m_probe->error());
        return;
    }
    const double length = session::toolLengthFromTrip(m_sensor, *trip);
    const QTableWidgetItem *it =
        m_measuringRow < m_grid->rowCount() ? m_grid->item(m_measuringRow, ToolColumn) : nullptr;
    int row = it && it->text().toInt() == m_measuringTool ? m_measuringRow : -1;
    for (int r = 0; r < m_grid->rowCount() && row < 0; ++r) {
        const QTableWidgetItem *t = m_grid->item(r, ToolColumn);
        if (t && t->text().toInt() == m_measuringTool)
            row = r;
    }
    if (row < 0) { // the row was removed meanwhile: added again
        addTool();
        row = m_grid->rowCount() - 1;
        m_grid->item(row, ToolColumn)->setText(QString::number(m_measuringTool));
        m_grid->item(row, PocketColumn)->setText(QString::number(m_measuringTool));
    }
    m_grid->item(row, LengthColumn)->setText(number(length));
    m_status->setText(tr("Tool %1 is %2 mm long (the sensor tripped at machine Z %3).")
                          .arg(m_measuringTool)
                          .arg(length, 0, 'f', 4)
                          .arg(*trip, 0, 'f', 4));
    if (save())
        emit measured(m_measuringTool, length);
}

void ToolTableDialog::updateMeasureButton()
{
    m_measure->setText(measuring() ? tr("S&top measuring") : tr("&Measure length"));
    m_measure->setToolTip(tr("Probes the selected tool on the tool length sensor (fast, then "
                             "slow) and writes its length into the table."));
}

void ToolTableDialog::closeEvent(QCloseEvent *event)
{
    if (measuring()) {
        m_probe->cancel();
        m_status->setText(tr("Measuring stopped: the tool goes back up to the sensor's "
                             "clearance. Close the table when it is up."));
        m_status->show();
        event->ignore();
        return;
    }
    QDialog::closeEvent(event);
}

void ToolTableDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ToolTableDialog::retranslate()
{
    setWindowTitle(tr("Tool table"));
    m_grid->setHorizontalHeaderLabels(
        {tr("Tool"), tr("Pocket"), tr("Length (mm)"), tr("Diameter (mm)"), tr("Comment")});
    m_file->setText(tr("File: %1").arg(m_path));
    m_add->setText(tr("&Add tool"));
    m_remove->setText(tr("&Remove tool"));
    m_save->setText(tr("&Save"));
    updateMeasureButton();
    m_close->setText(tr("&Close"));
}

} // namespace frezka::gui
