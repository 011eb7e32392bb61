#include "iopanel.h"

#include "ledwidget.h"

#include <QHBoxLayout>
#include <QLabel>

namespace frezka::gui {
namespace {
constexpr int kInputs[] = {0, 1, 2, 3, 4, 5, 6, 7, 14, 15}; // the inputs' numbers (INn)
}

// The status bar holds the connection, the unit and the state before this strip: at 1366 px the
// full captions (IN0 ... IN15, OUT0 ... OUT3) did not fit and were cut to "IN1", "OU'". The groups
// are named once and each lamp carries its number, with the full name as its tool tip.
IoPanel::IoPanel(QWidget *parent)
    : QWidget(parent)
{
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(2, 0, 2, 0);
    row->setSpacing(1);
    m_run = new LedWidget(QStringLiteral("RUN"), QColor(40, 220, 60), this);
    m_inta = new LedWidget(QStringLiteral("INTA"), QColor(255, 80, 40), this);
    row->addWidget(m_run);
    row->addWidget(m_inta);
    row->addSpacing(6);
    row->addWidget(new QLabel(QStringLiteral("IN"), this));
    for (int n : kInputs) {
        auto *led = new LedWidget(QString::number(n), QColor(250, 200, 40), this);
        led->setToolTip(QStringLiteral("IN%1").arg(n));
        m_inputs.push_back(led);
        row->addWidget(led);
    }
    row->addSpacing(6);
    row->addWidget(new QLabel(QStringLiteral("OUT"), this));
    for (int i = 0; i < 4; ++i) {
        auto *led = new LedWidget(QString::number(i), QColor(40, 160, 255), this);
        led->setToolTip(QStringLiteral("OUT%1").arg(i));
        m_outputs.push_back(led);
        row->addWidget(led);
    }
}

void IoPanel::setIo(const std::function<bool(int)> &inputOn,
                    const std::function<bool(int)> &outputOn, bool run, bool inta)
{
    for (std::size_t i = 0; i < m_inputs.size(); ++i)
        m_inputs[i]->setOn(inputOn(kInputs[i]));
    for (std::size_t i = 0; i < m_outputs.size(); ++i)
        m_outputs[i]->setOn(outputOn(int(i)));
    m_run->setOn(run);
    m_inta->setOn(inta);
}

void IoPanel::setRelayCount(int count)
{
    for (std::size_t i = 0; i < m_outputs.size(); ++i)
        m_outputs[i]->setVisible(int(i) < count);
    // GVE84 has only IN0-2.
    for (std::size_t i = 0; i < m_inputs.size(); ++i)
        m_inputs[i]->setVisible(count > 1 || i < 3);
}

bool IoPanel::inputLed(int n) const
{
    for (std::size_t i = 0; i < m_inputs.size(); ++i) {
        if (kInputs[i] == n)
            return m_inputs[i]->isOn();
    }
    return false;
}

bool IoPanel::outputLed(int n) const
{
    return n >= 0 && n < int(m_outputs.size()) && m_outputs[std::size_t(n)]->isOn();
}

} // namespace frezka::gui
