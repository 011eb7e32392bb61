#pragma once
// UnitsPanel: every unit on the machine's serial line (the profile's line.units; one row for a
// unit alone): address, name, type, identity and firmware as read at connect, state, position in
// mm (each unit's own profile's scales, computed by its driver core), inputs and outputs. For a
// unit other than the window's machine it jogs by steps (axis, step, direction) and stops it, so
// that another unit on the line jogs or idles while the machine runs its job. It renders the
// snapshots it is given and emits requests; it keeps no machine state.

#include "driver/link/machinestate.h"
#include "machine/machineconfig.h"

#include <QWidget>

#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace frezka::gui {

class UnitsPanel : public QWidget
{
    Q_OBJECT

public:
    // One unit on the line: its entry and its profile (scales, speeds).
    struct Unit
    {
        machine::LineUnitConfig entry;
        machine::MachineConfig config;
    };
    enum Column { Address, Name, Type, Identity, State, X, Y, Z, A, Inputs, Outputs, ColumnCount };

    explicit UnitsPanel(QWidget *parent = nullptr);
    // The panel's title (its dock's), translated.
    static QString title();

    // The units on the line in the profile's order; `machine` is the index of the window's
    // machine (its row says so; the jog controls list the others).
    void setUnits(const std::vector<Unit> &units, int machine);
    void showState(int unit, const driver::MachineState &state);
    // A refusal or error of a unit, shown in its row's state until its next state change.
    void showError(int unit, const QString &text);
    int unitCount() const { return int(m_units.size()); }
    const std::vector<Unit> &units() const { return m_units; }
    int machineIndex() const { return m_machine; }
    // The text of a cell (tests).
    QString text(int unit, Column column) const;
    // The unit the jog controls act on (-1: none, the line has only the machine).
    int jogUnit() const;
    void setJogUnit(int unit);
    void setJogAxis(int axis);
    void setJogStepMm(double stepMm);

signals:
    // Jog `unit` by distanceMm on axis (0..3 = X, Y, Z, A), at speedMmPerMin.
    void jogRequested(int unit, int axis, double distanceMm, double speedMmPerMin);
    // Stop what `unit` does (its jog; a job or homing is held).
    void stopRequested(int unit);
    // Make `unit` the window's machine (offered while every unit is idle).
    void machineChosen(int unit);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void jog(int direction);
    void updateControls();
    QString stateText(int unit) const;

    std::vector<Unit> m_units;
    std::vector<driver::MachineState> m_states;
    std::vector<QString> m_errors;
    int m_machine = 0;
    QTableWidget *m_table;
    QLabel *m_jogLabel;
    QComboBox *m_unitBox, *m_axisBox, *m_stepBox;
    QPushButton *m_minus, *m_plus, *m_stop, *m_choose;
};

} // namespace frezka::gui
