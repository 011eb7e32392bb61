#pragma once
// OutputsPanel: spindle on/off and speed, coolant, air blow and the profile's other outputs,
// the feed override (XM slider, XU/XD buttons for +/- 6.25 %) and the spindle override (50-150 %
// of every spindle speed sent).

#include "machine/machineconfig.h"

#include <QWidget>

#include <functional>
#include <utility>
#include <vector>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;
class QVBoxLayout;

namespace frezka::gui {

class OutputsPanel : public QWidget
{
    Q_OBJECT

public:
    explicit OutputsPanel(QWidget *parent = nullptr);
    void setMaxRpm(double rpm);
    // Extra outputs offered as toggles: caption and the function of the output.
    void setExtraOutputs(const std::vector<std::pair<QString, machine::OutputFunction>> &outputs);
    // Reflects the unit's state without emitting requests: the spindle, and whether the output
    // of each function (coolant, air blow, the extra ones) is on.
    void showState(bool spindleOn, const std::function<bool(machine::OutputFunction)> &isOn);
    // linkPercent > 0: the link holds the unit at that override
    // (MachineState::overrideHeldPercent).
    void showFeedOverride(int percent, int linkPercent = 0);
    // The spindle override as the driver applies it (issue 16 item 5).
    void showSpindleOverride(int percent);
    int feedOverride() const;
    double spindleRpm() const;

signals:
    void spindleRequested(bool on, double rpm);
    void coolantRequested(bool on);
    void airRequested(bool on);
    void outputRequested(machine::OutputFunction function, bool on);
    void feedOverrideRequested(int percent);
    void feedStepRequested(int direction); // +1 = XU, -1 = XD
    void spindleOverrideRequested(int percent);

protected:
    void changeEvent(QEvent *event) override;

private:
    // The constructor's parts, in the order the widgets are created (the focus chain).
    void createOutputs();
    void createFeedOverride();
    void createSpindleOverride();
    void retranslate();
    void showFeedValue(int percent);

    int m_linkPercent = 0;
    QPushButton *m_spindle, *m_coolant, *m_air;
    QDoubleSpinBox *m_rpm;
    QLabel *m_rpmLabel, *m_feedLabel, *m_feedValue;
    QSlider *m_feed;
    QPushButton *m_feedUp, *m_feedDown, *m_feedReset;
    QLabel *m_spindleOverrideLabel, *m_spindleOverrideValue;
    QSlider *m_spindleOverride;
    QPushButton *m_spindleOverrideReset;
    QVBoxLayout *m_extraBox;
    std::vector<std::pair<QPushButton *, machine::OutputFunction>> m_extra;
};

} // namespace frezka::gui
