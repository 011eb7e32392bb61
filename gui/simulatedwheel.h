#pragma once
// SimulatedWheel: the handwheel (MPG) of the built-in emulator, for running MPG mode without
// hardware: the unit's axis switch (X, Y, Z, 4th), its step switch (x1, x10, x100) and a wheel
// turned one detent per click of - / + (held: repeats). It only asks (turned); the emulated unit
// decides whether the wheel moves anything (MPG on, enabled in its EEPROM).

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;

namespace frezka::gui {

class SimulatedWheel : public QWidget
{
    Q_OBJECT

public:
    explicit SimulatedWheel(QWidget *parent = nullptr);
    // Turns as if - (detents < 0) or + was clicked |detents| times.
    void turn(int detents);

signals:
    // axis 0..3 (X, Y, Z, 4th), multiplier 1 / 10 / 100, detents signed.
    void turned(int axis, int multiplier, int detents);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QLabel *m_label;
    QComboBox *m_axis, *m_step;
    QPushButton *m_minus, *m_plus;
};

} // namespace frezka::gui
