#pragma once
// IoPanel: the unit's inputs (IN0-7, IN14, IN15), outputs (OUT0-3) and RUN / INTA as LEDs.

#include <QWidget>

#include <cstdint>
#include <vector>

namespace frezka::gui {

class LedWidget;

class IoPanel : public QWidget
{
    Q_OBJECT

public:
    explicit IoPanel(QWidget *parent = nullptr);
    // inputs: bit n = INn active (n = 0..15); outputs: bit n = OUTn on (n = 0..3).
    void setIo(std::uint16_t inputs, std::uint8_t outputs, bool run, bool inta);
    void setRelayCount(int count); // GVE84: 1 relay, GVE64/114: 4 outputs
    bool inputLed(int n) const;
    bool outputLed(int n) const;

private:
    std::vector<LedWidget *> m_inputs; // IN0..7, IN14, IN15
    std::vector<LedWidget *> m_outputs;
    LedWidget *m_run, *m_inta;
};

} // namespace frezka::gui
