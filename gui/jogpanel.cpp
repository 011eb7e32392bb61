#include "jogpanel.h"

#include "simulatedwheel.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace frezka::gui {
namespace {
constexpr char kAxes[] = "XYZA";
constexpr double kSteps[] = {0.01, 0.1, 1, 10};             // mm
constexpr double kInchSteps[] = {0.0001, 0.001, 0.01, 0.1}; // in (LinuxCNC AXIS's)
double stepOf(int i, LengthUnit unit)
{
    return unit == LengthUnit::Inch ? kInchSteps[i] : kSteps[i];
}
} // namespace

JogPanel::JogPanel(QWidget *parent)
    : QWidget(parent)
{
    QGridLayout *grid = createJogButtons();
    QHBoxLayout *steps = createStepChoice();
    QHBoxLayout *feedRow = createFeedRow();

    m_limits = new QLabel(this);
    m_limits->setObjectName(QStringLiteral("limitsOff"));
    m_limits->setWordWrap(true);
    m_limits->setStyleSheet(QStringLiteral("color: #b35900; font-weight: bold;"));
    m_limits->hide();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_limits);
    layout->addLayout(grid);
    layout->addLayout(steps);
    layout->addLayout(feedRow);
    m_wheel = new SimulatedWheel(this);
    m_wheel->hide();
    connect(m_wheel, &SimulatedWheel::turned, this, &JogPanel::wheelTurned);
    layout->addWidget(m_wheel);
    layout->addStretch();
    retranslate();
}

// The jog buttons (minus, home, plus) per axis and Home all below them.
QGridLayout *JogPanel::createJogButtons()
{
    auto *grid = new QGridLayout;
    for (int axis = 0; axis < 4; ++axis) {
        for (int d = 0; d < 2; ++d) {
            const int dir = d == 0 ? -1 : 1;
            auto *b = new QPushButton(QStringLiteral("%1%2")
                                          .arg(QLatin1Char(kAxes[axis]))
                                          .arg(dir < 0 ? QLatin1Char('-') : QLatin1Char('+')),
                                      this);
            b->setObjectName(QStringLiteral("jog%1%2")
                                 .arg(QLatin1Char(kAxes[axis]))
                                 .arg(dir < 0 ? QStringLiteral("Minus") : QStringLiteral("Plus")));
            b->setAutoRepeat(false);
            b->setFocusPolicy(Qt::NoFocus);
            connect(b, &QPushButton::pressed, this, [this, axis, dir] { jogKey(axis, dir, true); });
            connect(b, &QPushButton::released, this,
                    [this, axis, dir] { jogKey(axis, dir, false); });
            m_jog[std::size_t(axis * 2 + d)] = b;
            grid->addWidget(b, axis, d == 0 ? 0 : 2);
        }
        m_home[std::size_t(axis)] = new QPushButton(this);
        m_home[std::size_t(axis)]->setObjectName(
            QStringLiteral("home%1").arg(QLatin1Char(kAxes[axis])));
        m_home[std::size_t(axis)]->setFocusPolicy(Qt::NoFocus);
        connect(m_home[std::size_t(axis)], &QPushButton::clicked, this,
                [this, axis] { emit homeRequested(axis); });
        grid->addWidget(m_home[std::size_t(axis)], axis, 1);
    }
    m_homeAll = new QPushButton(this);
    m_homeAll->setObjectName(QStringLiteral("homeAll"));
    m_homeAll->setFocusPolicy(Qt::NoFocus);
    connect(m_homeAll, &QPushButton::clicked, this, [this] { emit homeRequested(-1); });
    grid->addWidget(m_homeAll, 4, 0, 1, 3);
    return grid;
}

// Continuous or one of the steps (1 mm checked).
QHBoxLayout *JogPanel::createStepChoice()
{
    auto *steps = new QHBoxLayout;
    m_stepLabel = new QLabel(this);
    steps->addWidget(m_stepLabel);
    m_steps = new QButtonGroup(this);
    m_continuous = new QRadioButton(this);
    m_continuous->setObjectName(QStringLiteral("jogContinuous"));
    m_steps->addButton(m_continuous, 0);
    steps->addWidget(m_continuous);
    for (int i = 0; i < 4; ++i) {
        auto *r = new QRadioButton(QString::number(kSteps[i]), this);
        r->setObjectName(QStringLiteral("jogStep%1").arg(i));
        m_steps->addButton(r, i + 1);
        steps->addWidget(r);
    }
    m_steps->button(3)->setChecked(true);
    // The arrows jog: a focused radio button would take them to move its selection instead.
    for (QAbstractButton *b : m_steps->buttons())
        b->setFocusPolicy(Qt::NoFocus);
    return steps;
}

// The jog feed and the MPG switch.
QHBoxLayout *JogPanel::createFeedRow()
{
    auto *feedRow = new QHBoxLayout;
    m_feedLabel = new QLabel(this);
    m_feed = new QDoubleSpinBox(this);
    m_feed->setObjectName(QStringLiteral("jogFeed"));
    m_feed->setRange(1, 100000);
    m_feed->setDecimals(0);
    m_feed->setValue(1000);
    m_feed->setSuffix(QStringLiteral(" mm/min"));
    m_mpg = new QCheckBox(this);
    m_mpg->setObjectName(QStringLiteral("mpg"));
    m_mpg->setFocusPolicy(Qt::NoFocus); // it switches the handwheel on the machine
    connect(m_mpg, &QCheckBox::toggled, this, &JogPanel::mpgToggled);
    feedRow->addWidget(m_feedLabel);
    feedRow->addWidget(m_feed, 1);
    feedRow->addWidget(m_mpg);
    return feedRow;
}

void JogPanel::setAxisCount(int count)
{
    m_axisCount = count;
    if (m_limits)
        showLimits();
    for (int axis = 0; axis < 4; ++axis) {
        m_jog[std::size_t(axis * 2)]->setVisible(axis < count);
        m_jog[std::size_t(axis * 2 + 1)]->setVisible(axis < count);
        m_home[std::size_t(axis)]->setVisible(axis < count && m_perAxisHoming);
    }
}

void JogPanel::setPerAxisHoming(bool available)
{
    m_perAxisHoming = available;
    setAxisCount(m_axisCount);
}

double JogPanel::stepMm() const
{
    const int id = m_steps->checkedId();
    return id <= 0 ? 0.0 : toMm(stepOf(id - 1, m_unit), m_unit);
}

void JogPanel::setStepMm(double stepMm)
{
    for (int i = 0; i < 4; ++i) {
        if (qFuzzyCompare(stepOf(i, m_unit), fromMm(stepMm, m_unit))) {
            m_steps->button(i + 1)->setChecked(true);
            return;
        }
    }
    m_continuous->setChecked(true);
}

double JogPanel::feedMmPerMin() const
{
    return toMm(m_feed->value(), m_unit);
}

void JogPanel::setUnit(LengthUnit unit)
{
    const double feedMm = feedMmPerMin();
    m_unit = unit;
    for (int i = 0; i < 4; ++i)
        m_steps->button(i + 1)->setText(QString::number(stepOf(i, unit)));
    m_feed->setDecimals(unit == LengthUnit::Inch ? 1 : 0);
    m_feed->setRange(fromMm(1, unit), fromMm(100000, unit));
    m_feed->setSuffix(QLatin1Char(' ') + feedSuffix(unit));
    m_feed->setValue(fromMm(feedMm, unit));
    retranslate();
}

void JogPanel::setMpgAvailable(bool available)
{
    m_mpgAvailable = available;
    m_mpg->setVisible(available);
    m_wheel->setVisible(m_mpgAvailable && m_wheelAvailable);
}

void JogPanel::setSimulatedWheelAvailable(bool available)
{
    m_wheelAvailable = available;
    m_wheel->setVisible(m_mpgAvailable && m_wheelAvailable);
}

void JogPanel::setMpgOn(bool on)
{
    const QSignalBlocker block(m_mpg);
    m_mpg->setChecked(on);
}

void JogPanel::setHomedAxes(const std::array<bool, 4> &homed, bool connected)
{
    m_homed = homed;
    m_connected = connected;
    showLimits();
}

// "not homed: limits off" while any axis of the machine is connected and not homed
// (machine/softlimits.h: its jog has no soft limits and runs at the homing speed).
void JogPanel::showLimits()
{
    QString axes;
    for (int axis = 0; axis < m_axisCount; ++axis) {
        if (!m_homed[std::size_t(axis)])
            axes += QLatin1Char(kAxes[axis]);
    }
    m_limits->setVisible(m_connected && !axes.isEmpty());
    m_limits->setText(tr("%1 not homed: soft limits off, slow jog").arg(axes));
    m_limits->setToolTip(
        tr("Before homing the counters do not say where the axes are: jogging ignores the "
           "soft limits and runs at most at the homing speed. Home the machine to have the "
           "limits and the full jog speed; a program asks for homing before it runs."));
}

void JogPanel::jogKey(int axis, int direction, bool pressed)
{
    if (axis < 0 || axis >= m_axisCount)
        return;
    const double step = stepMm();
    if (step > 0) {
        if (pressed)
            emit jogStepRequested(axis, direction * step, feedMmPerMin());
    } else if (pressed) {
        emit jogContinuousStarted(axis, direction, feedMmPerMin());
    } else {
        emit jogContinuousStopped();
    }
}

void JogPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void JogPanel::retranslate()
{
    for (int axis = 0; axis < 4; ++axis) {
        m_home[std::size_t(axis)]->setText(tr("Home %1").arg(QLatin1Char(kAxes[axis])));
        m_home[std::size_t(axis)]->setToolTip(
            tr("Find the home switch of %1").arg(QLatin1Char(kAxes[axis])));
    }
    m_homeAll->setText(tr("Home all"));
    m_homeAll->setToolTip(tr("Home every axis in the order of the machine profile"));
    m_stepLabel->setText(m_unit == LengthUnit::Inch ? tr("Step (in):") : tr("Step (mm):"));
    m_continuous->setText(tr("Continuous"));
    m_continuous->setToolTip(tr("Move while the button or key is held"));
    m_feedLabel->setText(tr("Jog feed:"));
    m_mpg->setText(tr("Handwheel (MPG)"));
    setToolTip(tr("Keyboard: arrows jog X/Y, Page Up/Page Down jog Z"));
    showLimits();
}

} // namespace frezka::gui
