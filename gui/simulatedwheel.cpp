#include "simulatedwheel.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace frezka::gui {

SimulatedWheel::SimulatedWheel(QWidget *parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("simulatedWheel"));
    m_label = new QLabel(this);
    m_axis = new QComboBox(this);
    m_axis->setObjectName(QStringLiteral("wheelAxis"));
    for (const char *axis : {"X", "Y", "Z", "4"})
        m_axis->addItem(QString::fromLatin1(axis));
    m_step = new QComboBox(this);
    m_step->setObjectName(QStringLiteral("wheelStep"));
    for (int multiplier : {1, 10, 100})
        m_step->addItem(QStringLiteral("x%1").arg(multiplier), multiplier);
    m_minus = new QPushButton(QStringLiteral("\u2212"), this);
    m_minus->setObjectName(QStringLiteral("wheelMinus"));
    m_plus = new QPushButton(QStringLiteral("+"), this);
    m_plus->setObjectName(QStringLiteral("wheelPlus"));
    for (QWidget *w : {static_cast<QWidget *>(m_axis), static_cast<QWidget *>(m_step),
                       static_cast<QWidget *>(m_minus), static_cast<QWidget *>(m_plus)})
        w->setFocusPolicy(Qt::NoFocus); // the arrows keep jogging
    for (QPushButton *b : {m_minus, m_plus}) {
        b->setAutoRepeat(true); // held: the wheel keeps turning, one detent per repeat
        b->setMaximumWidth(40);
    }
    connect(m_minus, &QPushButton::clicked, this, [this] { turn(-1); });
    connect(m_plus, &QPushButton::clicked, this, [this] { turn(1); });

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_label);
    layout->addWidget(m_axis);
    layout->addWidget(m_step);
    layout->addWidget(m_minus);
    layout->addWidget(m_plus);
    layout->addStretch();
    retranslate();
}

void SimulatedWheel::turn(int detents)
{
    if (detents != 0)
        emit turned(m_axis->currentIndex(), m_step->currentData().toInt(), detents);
}

void SimulatedWheel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void SimulatedWheel::retranslate()
{
    m_label->setText(tr("Simulated wheel:"));
    setToolTip(tr("Simulates the unit's MPG handwheel on the built-in emulator: choose the "
                  "axis and the step switch (x1 = 0.01 mm per detent), then turn with \u2212 / + "
                  "(hold to keep turning). It moves the axis only while Handwheel (MPG) is on."));
    m_axis->setToolTip(tr("The wheel's axis switch (4 = the fourth axis or the spindle, as the "
                          "unit's EEPROM sets it)"));
    m_step->setToolTip(tr("The wheel's step switch: x1 = 0.01 mm, x10 = 0.1 mm, x100 = 1 mm "
                          "per detent"));
    m_minus->setToolTip(tr("Turn the simulated wheel one detent back"));
    m_plus->setToolTip(tr("Turn the simulated wheel one detent forward"));
}

} // namespace frezka::gui
