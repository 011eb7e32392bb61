#pragma once
// OutputsPanel: spindle on/off and speed, coolant, air blow and the profile's other outputs,
// and the feed override (XM slider, XU/XD buttons for +/- 6.25 %).

#include <QWidget>

#include <cstdint>
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
    // Extra outputs offered as toggles: caption and port-0 bit.
    void setExtraOutputs(const std::vector<std::pair<QString, std::uint8_t>> &outputs);
    // Reflects the unit's state without emitting requests.
    void showState(bool spindleOn, bool coolantOn, bool airOn, std::uint8_t outputsOn);
    // linkPercent > 0: the link holds the unit at that override
    // (MachineState::overrideCeilingPercent).
    void showFeedOverride(int percent, int linkPercent = 0);
    int feedOverride() const;
    double spindleRpm() const;

signals:
    void spindleRequested(bool on, double rpm);
    void coolantRequested(bool on);
    void airRequested(bool on);
    void outputRequested(std::uint8_t bit, bool on);
    void feedOverrideRequested(int percent);
    void feedStepRequested(int direction); // +1 = XU, -1 = XD

protected:
    void changeEvent(QEvent *event) override;

private:
    // The constructor's parts, in the order the widgets are created (the focus chain).
    void createOutputs();
    void createFeedOverride();
    void retranslate();
    void showFeedValue(int percent);

    int m_linkPercent = 0;
    QPushButton *m_spindle, *m_coolant, *m_air;
    QDoubleSpinBox *m_rpm;
    QLabel *m_rpmLabel, *m_feedLabel, *m_feedValue;
    QSlider *m_feed;
    QPushButton *m_feedUp, *m_feedDown, *m_feedReset;
    QVBoxLayout *m_extraBox;
    std::vector<std::pair<QPushButton *, std::uint8_t>> m_extra;
};

} // namespace frezka::gui
