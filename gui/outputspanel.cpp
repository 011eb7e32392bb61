#include "outputspanel.h"

#include "driver/link/machinestate.h"

#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>

namespace frezka::gui {

OutputsPanel::OutputsPanel(QWidget *parent)
    : QWidget(parent)
{
    createOutputs();
    createFeedOverride();
    createSpindleOverride();

    auto *grid = new QGridLayout;
    grid->addWidget(m_spindle, 0, 0);
    grid->addWidget(m_rpmLabel, 0, 1);
    grid->addWidget(m_rpm, 0, 2);
    grid->addWidget(m_coolant, 1, 0);
    grid->addWidget(m_air, 1, 1);
    auto *feedRow = new QHBoxLayout;
    feedRow->addWidget(m_feedLabel);
    feedRow->addWidget(m_feedDown);
    feedRow->addWidget(m_feed, 1);
    feedRow->addWidget(m_feedUp);
    feedRow->addWidget(m_feedValue);
    feedRow->addWidget(m_feedReset);
    m_extraBox = new QVBoxLayout;
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(grid);
    layout->addLayout(m_extraBox);
    layout->addLayout(feedRow);
    auto *spindleRow = new QHBoxLayout;
    spindleRow->addWidget(m_spindleOverrideLabel);
    spindleRow->addWidget(m_spindleOverride, 1);
    spindleRow->addWidget(m_spindleOverrideValue);
    spindleRow->addWidget(m_spindleOverrideReset);
    layout->addLayout(spindleRow);
    layout->addStretch();
    retranslate();
}

// The spindle (with its speed), coolant and air buttons.
void OutputsPanel::createOutputs()
{
    auto toggle = [this](const char *name) {
        auto *b = new QPushButton(this);
        b->setObjectName(QLatin1String(name));
        b->setCheckable(true);
        b->setFocusPolicy(Qt::NoFocus); // no key acts on a machine button through its focus
        return b;
    };
    m_spindle = toggle("spindle");
    m_coolant = toggle("coolant");
    m_air = toggle("air");
    m_rpm = new QDoubleSpinBox(this);
    m_rpm->setObjectName(QStringLiteral("spindleRpm"));
    m_rpm->setDecimals(0);
    m_rpm->setRange(0, 24000);
    m_rpm->setValue(12000);
    m_rpm->setSuffix(QStringLiteral(" rpm"));
    m_rpmLabel = new QLabel(this);
    connect(m_spindle, &QPushButton::clicked, this,
            [this](bool on) { emit spindleRequested(on, m_rpm->value()); });
    connect(m_rpm, &QDoubleSpinBox::editingFinished, this, [this] {
        if (m_spindle->isChecked())
            emit spindleRequested(true, m_rpm->value());
    });
    connect(m_coolant, &QPushButton::clicked, this, &OutputsPanel::coolantRequested);
    connect(m_air, &QPushButton::clicked, this, &OutputsPanel::airRequested);
}

// The feed override: the slider, its value, the steps and 100 %.
void OutputsPanel::createFeedOverride()
{
    m_feedLabel = new QLabel(this);
    m_feed = new QSlider(Qt::Horizontal, this);
    m_feed->setObjectName(QStringLiteral("feedOverride"));
    m_feed->setRange(driver::kOverrideMinPercent, driver::kOverrideMaxPercent);
    m_feed->setValue(100);
    m_feed->setPageStep(10);
    m_feedValue = new QLabel(QStringLiteral("100 %"), this);
    m_feedValue->setMinimumWidth(QFontMetrics(font()).horizontalAdvance(QStringLiteral("200 %")));
    connect(m_feed, &QSlider::valueChanged, this, [this](int v) { showFeedValue(v); });
    connect(m_feed, &QSlider::sliderReleased, this,
            [this] { emit feedOverrideRequested(m_feed->value()); });
    connect(m_feed, &QSlider::actionTriggered, this, [this](int action) {
        if (action != QAbstractSlider::SliderMove)
            QMetaObject::invokeMethod(
                this, [this] { emit feedOverrideRequested(m_feed->value()); },
                Qt::QueuedConnection);
    });
    m_feedUp = new QPushButton(QStringLiteral("+"), this);
    m_feedUp->setObjectName(QStringLiteral("feedUp"));
    m_feedDown = new QPushButton(QStringLiteral("−"), this);
    m_feedDown->setObjectName(QStringLiteral("feedDown"));
    m_feedReset = new QPushButton(QStringLiteral("100 %"), this);
    m_feedReset->setObjectName(QStringLiteral("feedReset"));
    for (auto *b : {m_feedUp, m_feedDown, m_feedReset}) {
        b->setMaximumWidth(60);
        b->setFocusPolicy(Qt::NoFocus);
    }
    m_feed->setFocusPolicy(Qt::NoFocus); // the arrows jog; the override has its keys (+, -, 0)
    connect(m_feedUp, &QPushButton::clicked, this, [this] { emit feedStepRequested(+1); });
    connect(m_feedDown, &QPushButton::clicked, this, [this] { emit feedStepRequested(-1); });
    connect(m_feedReset, &QPushButton::clicked, this, [this] {
        m_feed->setValue(100);
        emit feedOverrideRequested(100);
    });
}

// The spindle override: the slider, its value and 100 %.
void OutputsPanel::createSpindleOverride()
{
    m_spindleOverrideLabel = new QLabel(this);
    m_spindleOverride = new QSlider(Qt::Horizontal, this);
    m_spindleOverride->setObjectName(QStringLiteral("spindleOverride"));
    m_spindleOverride->setRange(driver::kSpindleOverrideMinPercent,
                                driver::kSpindleOverrideMaxPercent);
    m_spindleOverride->setValue(100);
    m_spindleOverride->setPageStep(10);
    m_spindleOverride->setFocusPolicy(Qt::NoFocus); // the arrows jog
    m_spindleOverrideValue = new QLabel(QStringLiteral("100 %"), this);
    m_spindleOverrideValue->setMinimumWidth(m_feedValue->minimumWidth());
    auto request = [this] { emit spindleOverrideRequested(m_spindleOverride->value()); };
    connect(m_spindleOverride, &QSlider::valueChanged, this,
            [this](int v) { m_spindleOverrideValue->setText(QStringLiteral("%1 %").arg(v)); });
    connect(m_spindleOverride, &QSlider::sliderReleased, this, request);
    connect(m_spindleOverride, &QSlider::actionTriggered, this, [this, request](int action) {
        if (action != QAbstractSlider::SliderMove)
            QMetaObject::invokeMethod(this, request, Qt::QueuedConnection);
    });
    m_spindleOverrideReset = new QPushButton(QStringLiteral("100 %"), this);
    m_spindleOverrideReset->setObjectName(QStringLiteral("spindleOverrideReset"));
    m_spindleOverrideReset->setMaximumWidth(60);
    m_spindleOverrideReset->setFocusPolicy(Qt::NoFocus);
    connect(m_spindleOverrideReset, &QPushButton::clicked, this, [this] {
        m_spindleOverride->setValue(100);
        emit spindleOverrideRequested(100);
    });
}

void OutputsPanel::showSpindleOverride(int percent)
{
    if (m_spindleOverride->isSliderDown())
        return;
    const QSignalBlocker block(m_spindleOverride);
    m_spindleOverride->setValue(percent);
    m_spindleOverrideValue->setText(QStringLiteral("%1 %").arg(percent));
}

void OutputsPanel::setMaxRpm(double rpm)
{
    m_rpm->setRange(0, rpm);
}

void OutputsPanel::setExtraOutputs(
    const std::vector<std::pair<QString, machine::OutputFunction>> &outputs)
{
    for (auto &[b, function] : m_extra)
        delete b;
    m_extra.clear();
    for (const auto &[caption, function] : outputs) {
        auto *b = new QPushButton(caption, this);
        b->setCheckable(true);
        b->setObjectName(QStringLiteral("output%1").arg(int(function)));
        b->setFocusPolicy(Qt::NoFocus);
        const machine::OutputFunction f = function;
        connect(b, &QPushButton::clicked, this,
                [this, f](bool on) { emit outputRequested(f, on); });
        m_extraBox->addWidget(b);
        m_extra.emplace_back(b, function);
    }
}

void OutputsPanel::showState(bool spindleOn,
                             const std::function<bool(machine::OutputFunction)> &isOn)
{
    m_spindle->setChecked(spindleOn);
    m_coolant->setChecked(isOn(machine::OutputFunction::Coolant));
    m_air->setChecked(isOn(machine::OutputFunction::AirBlow));
    for (auto &[b, function] : m_extra)
        b->setChecked(isOn(function));
}

void OutputsPanel::showFeedOverride(int percent, int linkPercent)
{
    m_linkPercent = linkPercent;
    if (m_feed->isSliderDown())
        return;
    const QSignalBlocker block(m_feed);
    m_feed->setValue(percent);
    showFeedValue(percent);
}

// The operator's percentage, and beside it what the unit runs while the link cannot feed more.
void OutputsPanel::showFeedValue(int percent)
{
    const bool held = m_linkPercent > 0 && m_linkPercent < percent;
    m_feedValue->setText(held ? tr("%1 % (runs %2 %)").arg(percent).arg(m_linkPercent)
                              : QStringLiteral("%1 %").arg(percent));
    m_feedValue->setStyleSheet(held ? QStringLiteral("color: #b35900;") : QString());
    m_feedValue->setToolTip(
        held ? tr("The serial link cannot carry the program's motion at %1 %: the unit runs %2 % "
                  "until the motion ahead is slow enough, so that it never runs dry.")
                   .arg(percent)
                   .arg(m_linkPercent)
             : QString());
}

int OutputsPanel::feedOverride() const
{
    return m_feed->value();
}

double OutputsPanel::spindleRpm() const
{
    return m_rpm->value();
}

void OutputsPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void OutputsPanel::retranslate()
{
    m_spindle->setText(tr("Spindle"));
    m_spindle->setToolTip(tr("Switch the spindle on or off at the speed on the right"));
    m_rpmLabel->setText(tr("Speed:"));
    m_coolant->setText(tr("Coolant"));
    m_air->setText(tr("Air blow"));
    m_feedLabel->setText(tr("Feed:"));
    m_feed->setToolTip(tr("Feed override in percent of the programmed feed (XM)"));
    m_feedUp->setToolTip(tr("Raise every queued speed by 6.25 % (XU)"));
    m_feedDown->setToolTip(tr("Lower every queued speed by 6.25 % (XD)"));
    showFeedValue(m_feed->value());
    m_spindleOverrideLabel->setText(tr("Spindle:"));
    m_spindleOverride->setToolTip(
        tr("Spindle override in percent of the programmed speed: the turning spindle at once, "
           "and every spindle speed of the rest of the job"));
    m_spindleOverrideReset->setToolTip(tr("Spindle speed as programmed"));
}

} // namespace frezka::gui
