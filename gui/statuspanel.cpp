#include "statuspanel.h"

#include "session/runworkflow.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>

namespace frezka::gui {

using driver::MachineMode;

StatusPanel::StatusPanel(QWidget *parent)
    : QWidget(parent)
{
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(6, 6, 6, 6);
    grid->setVerticalSpacing(3);
    m_state = new QLabel(this);
    m_state->setObjectName(QStringLiteral("statusState"));
    m_state->setAlignment(Qt::AlignCenter);
    m_state->setMinimumHeight(44);
    QFont big = m_state->font();
    big.setPointSizeF(big.pointSizeF() * 1.9);
    big.setBold(true);
    m_state->setFont(big);
    grid->addWidget(m_state, 0, 0, 1, 2);
    m_feed = addRow(1, &m_feedCaption, "statusFeed");
    QFont figure = m_feed->font();
    figure.setPointSizeF(figure.pointSizeF() * 1.35);
    figure.setBold(true);
    m_feed->setFont(figure);
    m_programmedFeed = new QLabel(this);
    m_programmedFeed->setObjectName(QStringLiteral("statusProgrammedFeed"));
    grid->addWidget(m_programmedFeed, 2, 1);
    m_spindle = addRow(3, &m_spindleCaption, "statusSpindle");
    m_tool = addRow(4, &m_toolCaption, "statusTool");
    m_outputs = addRow(5, &m_outputsCaption, "statusOutputs");
    m_modes = addRow(6, &m_modesCaption, "statusModes");
    m_modes->setWordWrap(true);
    m_modes->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_homed = addRow(7, &m_homedCaption, "statusHomed");
    m_connection = addRow(8, &m_connectionCaption, "statusConnection");
    m_connection->setWordWrap(true);
    grid->setColumnStretch(1, 1);
    grid->setRowStretch(9, 1);
    grid->setSizeConstraint(QLayout::SetMinimumSize); // its dock never squeezes the rows together
    retranslate();
}

QLabel *StatusPanel::addRow(int row, QLabel **caption, const char *name)
{
    auto *grid = static_cast<QGridLayout *>(layout());
    *caption = new QLabel(this);
    (*caption)->setAlignment(Qt::AlignRight | Qt::AlignTop);
    auto *value = new QLabel(this);
    value->setObjectName(QLatin1String(name));
    grid->addWidget(*caption, row, 0);
    grid->addWidget(value, row, 1);
    return value;
}

QString StatusPanel::stateColour(MachineMode mode)
{
    switch (mode) {
    case MachineMode::Idle:
        return QStringLiteral("#2e7d32"); // green: ready
    case MachineMode::Running:
    case MachineMode::Homing:
    case MachineMode::Jogging:
        return QStringLiteral("#1565c0"); // blue: moving
    case MachineMode::Stopping:
    case MachineMode::Paused:
    case MachineMode::ToolLifted:
        return QStringLiteral("#e68a00"); // amber: held
    case MachineMode::Alarm:
    case MachineMode::LinkLost:
        return QStringLiteral("#c62828"); // red: needs the operator
    case MachineMode::Disconnected:
    case MachineMode::Connecting:
        break;
    }
    return QStringLiteral("#757575"); // grey: no machine
}

void StatusPanel::show(const StatusView &view)
{
    m_view = view;
    render();
}

void StatusPanel::setUnit(LengthUnit unit)
{
    m_unit = unit;
    render();
}

void StatusPanel::render()
{
    const StatusView &v = m_view;
    m_state->setText(session::RunWorkflow::modeText(v.mode));
    m_state->setStyleSheet(QStringLiteral("QLabel { background: %1; color: white; "
                                          "border-radius: 4px; padding: 4px; }")
                               .arg(stateColour(v.mode)));
    m_feed->setText(
        QStringLiteral("%1 %2").arg(formatFeed(v.actualFeedMmPerMin, m_unit), feedSuffix(m_unit)));
    const QString override =
        v.overrideHeldPercent > 0
            ? tr("%1 % (runs %2 %)").arg(v.overridePercent).arg(v.overrideHeldPercent)
            : QStringLiteral("%1 %").arg(v.overridePercent);
    m_programmedFeed->setText(
        v.programmedFeedMmPerMin < 0
            ? tr("override %1").arg(override)
            : tr("programmed %1 %2 × %3")
                  .arg(formatFeed(v.programmedFeedMmPerMin, m_unit), feedSuffix(m_unit), override));
    const QString direction = v.spindleDirection > 0   ? tr("clockwise (M3)")
                              : v.spindleDirection < 0 ? tr("counter-clockwise (M4)")
                                                       : QString();
    const QString spindle =
        v.spindleOn ? (direction.isEmpty()
                           ? tr("on · %1 rpm").arg(v.spindleRpm, 0, 'f', 0)
                           : tr("on · %1 · %2 rpm").arg(direction).arg(v.spindleRpm, 0, 'f', 0))
                    : tr("off");
    m_spindle->setText(v.spindleOverridePercent == 100
                           ? spindle
                           : tr("%1 (override %2 %)").arg(spindle).arg(v.spindleOverridePercent));
    m_tool->setText(v.tool < 0    ? QStringLiteral("–")
                    : v.tool == 0 ? tr("none (T0)")
                                  : QStringLiteral("T%1").arg(v.tool));
    QStringList outputs;
    for (const auto &[caption, on] : v.outputs)
        outputs << (on ? tr("%1 on") : tr("%1 off")).arg(caption);
    m_outputs->setText(outputs.join(QStringLiteral(" · ")));
    m_modes->setText(v.modes.isEmpty() ? QStringLiteral("–") : v.modes);
    static const char kAxes[] = "XYZA";
    QStringList homed;
    for (int a = 0; a < v.axisCount && a < 4; ++a)
        if (v.homed[std::size_t(a)])
            homed << QString(QLatin1Char(kAxes[a]));
    m_homed->setText(homed.isEmpty() ? tr("none") : homed.join(QLatin1Char(' ')));
    m_connection->setText(v.connection);
}

void StatusPanel::retranslate()
{
    m_feedCaption->setText(tr("Feed"));
    m_spindleCaption->setText(tr("Spindle"));
    m_toolCaption->setText(tr("Tool"));
    m_outputsCaption->setText(tr("Outputs"));
    m_modesCaption->setText(tr("Modes"));
    m_homedCaption->setText(tr("Homed"));
    m_connectionCaption->setText(tr("Connection"));
    render();
}

void StatusPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace frezka::gui
