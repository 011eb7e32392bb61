#pragma once
// IoPanel: the unit's inputs (IN0-7, IN14, IN15), outputs (OUT0-3) and RUN / INTA as LEDs.

#include <QWidget>

#include <functional>
#include <vector>

namespace frezka::gui {

class LedWidget;

class IoPanel : public QWidget
{
    Q_OBJECT

public:
    explicit IoPanel(QWidget *parent = nullptr);
    // Lights each input INn (n = 0..7, 14, 15) as inputOn(n) says and each output OUTn
    // (n = 0..3) as outputOn(n) says (the machine state's logical I/O: no port bits here).
    void setIo(const std::function<bool(int)> &inputOn, const std::function<bool(int)> &outputOn,
               bool run, bool inta);
    void setRelayCount(int count); // GVE84: 1 relay, GVE64/114: 4 outputs
    bool inputLed(int n) const;
    bool outputLed(int n) const;

private:
    std::vector<LedWidget *> m_inputs; // IN0..7, IN14, IN15
    std::vector<LedWidget *> m_outputs;
    LedWidget *m_run, *m_inta;
};

} // namespace frezka::gui
