#include "iopanel.h"

#include "ledwidget.h"

#include <QHBoxLayout>

namespace frezka::gui {
namespace {
constexpr int kInputBits[] = {0, 1, 2, 3, 4, 5, 6, 7, 14, 15};
}

IoPanel::IoPanel(QWidget *parent)
    : QWidget(parent)
{
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(2, 0, 2, 0);
    row->setSpacing(2);
    m_run = new LedWidget(QStringLiteral("RUN"), QColor(40, 220, 60), this);
    m_inta = new LedWidget(QStringLiteral("INTA"), QColor(255, 80, 40), this);
    row->addWidget(m_run);
    row->addWidget(m_inta);
    row->addSpacing(8);
    for (int bit : kInputBits) {
        auto *led = new LedWidget(QStringLiteral("IN%1").arg(bit), QColor(250, 200, 40), this);
        m_inputs.push_back(led);
        row->addWidget(led);
    }
    row->addSpacing(8);
    for (int i = 0; i < 4; ++i) {
        auto *led = new LedWidget(QStringLiteral("OUT%1").arg(i), QColor(40, 160, 255), this);
        m_outputs.push_back(led);
        row->addWidget(led);
    }
}

void IoPanel::setIo(std::uint16_t inputs, std::uint8_t outputs, bool run, bool inta)
{
    for (std::size_t i = 0; i < m_inputs.size(); ++i)
        m_inputs[i]->setOn(inputs & (1u << kInputBits[i]));
    for (std::size_t i = 0; i < m_outputs.size(); ++i)
        m_outputs[i]->setOn(outputs & (1u << i));
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
        if (kInputBits[i] == n)
            return m_inputs[i]->isOn();
    }
    return false;
}

bool IoPanel::outputLed(int n) const
{
    return n >= 0 && n < int(m_outputs.size()) && m_outputs[std::size_t(n)]->isOn();
}

} // namespace frezka::gui
