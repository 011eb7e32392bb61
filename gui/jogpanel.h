#pragma once
// JogPanel: jog buttons per axis (step 0.01 / 0.1 / 1 / 10 mm or continuous while held),
// jog feed, homing (all / per axis), the MPG switch and the built-in emulator's handwheel. It only
// asks; the soft-limit policy (machine/softlimits.h) decides in the driver. Shows which axes are
// not homed (limits off).

#include "displayunits.h"

#include <QWidget>

#include <array>
#include <cstdint>

class QButtonGroup;
class QCheckBox;
class QDoubleSpinBox;
class QGridLayout;
class QHBoxLayout;
class QLabel;
class QPushButton;
class QRadioButton;

namespace frezka::gui {

class SimulatedWheel;

class JogPanel : public QWidget
{
    Q_OBJECT

public:
    explicit JogPanel(QWidget *parent = nullptr);
    void setAxisCount(int count);
    // 0 = continuous, otherwise the step in mm.
    double stepMm() const;
    void setStepMm(double stepMm);
    double feedMmPerMin() const;
    // The steps and the feed in mm or inch (0.0001 .. 0.1 in); stepMm() and feedMmPerMin()
    // stay in mm. The chosen step keeps its place in the row.
    void setUnit(LengthUnit unit);
    void setMpgAvailable(bool available);
    // The simulated handwheel (SimulatedWheel) under the MPG switch: only while connected to
    // the built-in emulator of a unit with an MPG.
    void setSimulatedWheelAvailable(bool available);
    // Per-axis homing buttons (hidden while the driver homes only the whole machine).
    void setPerAxisHoming(bool available);
    void setMpgOn(bool on);
    // Shows "X Y not homed: soft limits off, slow jog" while connected with axes not homed.
    // Which axes (X, Y, Z, A) have been homed since connecting.
    void setHomedAxes(const std::array<bool, 4> &homed, bool connected);
    // Jog as if the button of axis (0..3) in direction (+1/-1) was clicked (keyboard).
    void jogKey(int axis, int direction, bool pressed);

signals:
    void jogStepRequested(int axis, double deltaMm, double feedMmPerMin);
    void jogContinuousStarted(int axis, int direction, double feedMmPerMin);
    void jogContinuousStopped();
    void homeRequested(int axis); // -1 = all axes in the profile's order
    void mpgToggled(bool on);
    // The simulated handwheel turned (SimulatedWheel::turned).
    void wheelTurned(int axis, int multiplier, int detents);

protected:
    void changeEvent(QEvent *event) override;

private:
    // The constructor's parts, in the order the widgets are created (the focus chain).
    QGridLayout *createJogButtons();
    QHBoxLayout *createStepChoice();
    QHBoxLayout *createFeedRow();
    void retranslate();
    void showLimits();

    std::array<QPushButton *, 8> m_jog{};
    std::array<QPushButton *, 4> m_home{};
    QPushButton *m_homeAll;
    QButtonGroup *m_steps;
    QRadioButton *m_continuous;
    QDoubleSpinBox *m_feed;
    QLabel *m_feedLabel, *m_stepLabel;
    QCheckBox *m_mpg;
    SimulatedWheel *m_wheel;
    bool m_mpgAvailable = true;
    bool m_wheelAvailable = false;
    QLabel *m_limits = nullptr;
    std::array<bool, 4> m_homed{};
    bool m_connected = false;
    int m_axisCount = 4;
    bool m_perAxisHoming = true;
    LengthUnit m_unit = LengthUnit::Mm;
};

} // namespace frezka::gui
