#pragma once
// Machine › Probe work zero (issue 19 item 2): the guided steps of finding the work's zero by
// probing on the connected unit or the built-in emulator, each with a picture of the setup
// (ProbeSetupPicture) and what to do: Z from a touch plate of known thickness, X or Y from an
// edge, X and Y from an outside or an inside corner, with the tool's diameter taken into
// account. The probing is session::HeightProbe's (fast then slow G38.2; the probe input read
// before each move; a probe that does not touch within the travel is an error and the tool
// goes back to its start); the result is set into the window's active work system (G92 kept,
// as G10 L20). Stop (or closing the dialog) stops the probe and brings the tool back.

#include "machine/machineconfig.h"

#include <QDialog>

#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace frezka::session {
class HeightProbe;
class MachineLink;
class WorkOffsets;
} // namespace frezka::session

namespace frezka::gui {

class ProbeSetupPicture;

class ProbeZeroDialog : public QDialog
{
    Q_OBJECT

public:
    // The kinds in the order of the dialog's list.
    enum Kind { ZPlate, XEdge, YEdge, OutsideCorner, InsideCorner };

    ProbeZeroDialog(session::MachineLink &link, const machine::MachineConfig &config,
                    session::WorkOffsets &offsets, QWidget *parent = nullptr);

    void setKind(Kind kind);
    Kind kind() const;
    // Starts probing with the dialog's values; false with the reason shown when it cannot.
    // Pressed again while probing: stops.
    bool probe();
    bool isProbing() const;
    QString statusText() const;
    QString errorText() const;
    ProbeSetupPicture *picture() const { return m_picture; }

signals:
    void probingFinished(bool ok);

protected:
    void changeEvent(QEvent *event) override;
    void closeEvent(QCloseEvent *event) override;

private:
    void retranslate();
    void updateSetup();
    void onFinished(bool ok);
    bool startAxis(int axis);
    void apply();
    void showError(const QString &text);

    session::MachineLink &m_link;
    machine::MachineConfig m_config;
    session::WorkOffsets &m_offsets;
    session::HeightProbe *m_probe;
    ProbeSetupPicture *m_picture;
    QComboBox *m_kind, *m_xDirection, *m_yDirection;
    QDoubleSpinBox *m_plate, *m_diameter, *m_travel, *m_reach, *m_feed, *m_retract;
    QLabel *m_steps, *m_status, *m_error;
    QLabel *m_kindLabel, *m_xLabel, *m_yLabel, *m_plateLabel, *m_diameterLabel, *m_travelLabel,
        *m_reachLabel, *m_feedLabel, *m_retractLabel;
    QPushButton *m_probeButton, *m_close;
    std::vector<int> m_axes;     // the axes of this probing, in order (2: Z)
    std::vector<double> m_trips; // their trip points, machine mm
};

} // namespace frezka::gui
