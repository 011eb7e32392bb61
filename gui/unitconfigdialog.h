#pragma once
// UnitConfigDialog: what the vendor's configuration utility does — read the unit's EEPROM,
// show it decoded for its variant next to what the machine profile asks, write the differences
// on request (after asking: the unit keeps what is written) and read them back to verify.
// Commands go through the controller's raw-command
// path one at a time (the link is half duplex); each reply is matched to its command.

#include "machine/machineconfig.h"

#include <QDialog>
#include <QTimer>

#include <deque>
#include <optional>
#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace frezka::driver {
class MachineController;
struct MachineError;
} // namespace frezka::driver

namespace frezka::gui {

class UnitConfigDialog : public QDialog
{
    Q_OBJECT

public:
    UnitConfigDialog(driver::MachineController *controller, const machine::MachineConfig &profile,
                     QWidget *parent = nullptr);

    void setProfile(const machine::MachineConfig &profile);
    // Reads every entry of the profile's EEPROM image from the unit.
    void readUnit();
    // Writes the entries that differ (all = every entry), then reads them back.
    void writeUnit(bool all = false);
    // What the Write buttons do: asks first (a non-modal question, object name
    // "confirmEepromWrite"); writeUnit(all) only when the operator confirms.
    void requestWrite(bool all);
    bool isBusy() const { return !m_queue.empty() || m_current.has_value(); }

    struct Row
    {
        machine::EepromEntry wanted; // from the profile
        std::optional<double> unit;  // read from the unit
        bool verified = false;       // read back after a write and equal
    };
    const std::vector<Row> &rows() const { return m_rows; }
    int differences() const;
    QString statusText() const;

signals:
    void finished(bool ok);

protected:
    void changeEvent(QEvent *event) override;

private:
    struct Op
    {
        QString command; // without "!0"
        int row = -1;
        bool write = false;
        bool verify = false; // a read after a write
    };
    void next();
    void onLogLine(const QString &line);
    void onError(const driver::MachineError &error);
    void fail(const QString &why);
    void refreshTable();
    void retranslate();

    driver::MachineController *m_controller;
    machine::MachineConfig m_profile;
    std::vector<Row> m_rows;
    std::deque<Op> m_queue;
    std::optional<Op> m_current;
    QTimer m_timeout;
    bool m_failed = false;
    QTableWidget *m_table;
    QLabel *m_status;
    QPushButton *m_read, *m_writeDiff, *m_writeAll, *m_close;
};

} // namespace frezka::gui
