#pragma once
// Machine › Tool table: the profile's tool table (LinuxCNC .tbl, gcode/tooltable.h) as a grid
// of tool number, pocket, length (Z), diameter and comment; add, remove, edit, save. Saving
// checks every row first (a row that cannot be read is named with what to fix, nothing is
// written) and writes the file atomically. The other words of a line (X Y A offsets, lathe
// angles, orientation) are kept as they were read.

#include "gcode/tooltable.h"
#include "machine/machineconfig.h"

#include <QDialog>

#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace frezka::session {
class HeightProbe;
class MachineLink;
} // namespace frezka::session

namespace frezka::gui {

class ToolTableDialog : public QDialog
{
    Q_OBJECT

public:
    enum Column { ToolColumn, PocketColumn, LengthColumn, DiameterColumn, CommentColumn };

    // path: the table file (created by the first save when it does not exist).
    explicit ToolTableDialog(const QString &path, QWidget *parent = nullptr);

    QString path() const { return m_path; }
    QTableWidget *grid() const { return m_grid; }
    QString errorText() const; // what the last load or save refused, empty when none
    // Reads the file into the grid; false (with the error shown) when it cannot be read.
    bool reload();
    void addTool();            // a new row with the next free tool number
    void removeSelectedTool(); // the current row
    // The grid as a table; false with *error (translated, naming the row) when a row is bad.
    bool tableFromGrid(gcode::ToolTable *table, QString *error) const;
    bool save(); // checks, writes atomically; saved() on success
    // The machine the tool sensor is on (issue 19 item 1): Measure probes the selected tool's
    // length on the profile's tools.sensor (session/toollength.h), puts it in the row and saves.
    void setToolSensor(session::MachineLink &link, const machine::MachineConfig &config);
    // Starts measuring the current row's tool; false with the reason shown when it cannot.
    // measured(tool, length) or the error follows; a second call while measuring stops it (the
    // tool goes back up to the sensor's clearance).
    bool measureSelectedTool();
    bool measuring() const;

signals:
    void saved(const gcode::ToolTable &table);
    void measured(int tool, double lengthMm);

protected:
    void changeEvent(QEvent *event) override;
    // While measuring: the probe stopped (the tool goes back up), the dialog stays open.
    void closeEvent(QCloseEvent *event) override;

private:
    void retranslate();
    void setRow(int row, const gcode::ToolEntry &entry);
    void showError(const QString &text);
    void measureFinished(bool ok);
    void updateMeasureButton();

    QString m_path;
    QTableWidget *m_grid;
    QLabel *m_file;
    QLabel *m_error;
    QPushButton *m_add, *m_remove, *m_save, *m_close, *m_measure;
    QLabel *m_status;
    session::HeightProbe *m_probe = nullptr;
    machine::ToolSensorConfig m_sensor;
    int m_measuringRow = -1, m_measuringTool = 0;
    std::vector<gcode::ToolEntry> m_rows; // as read, for the words the grid does not show
};

} // namespace frezka::gui
