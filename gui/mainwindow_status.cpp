// MainWindow: the status panel's figures (issue 16 item 1), from the driver's snapshot and the
// loaded program at the line being cut.
#include "mainwindow.h"

#include "statuspanel.h"

#include "machine/machineconfig.h"
#include "session/programmodes.h"

namespace frezka::gui {

namespace {

// The outputs the status panel lists when the profile has an output carrying them.
struct ShownOutput
{
    machine::OutputFunction function;
    const char *caption;
};
constexpr ShownOutput kShownOutputs[] = {
    {machine::OutputFunction::Coolant, QT_TRANSLATE_NOOP("frezka::gui::MainWindow", "Coolant")},
    {machine::OutputFunction::AirBlow, QT_TRANSLATE_NOOP("frezka::gui::MainWindow", "Air blow")},
    {machine::OutputFunction::Laser, QT_TRANSLATE_NOOP("frezka::gui::MainWindow", "Laser")},
    {machine::OutputFunction::CoverLock,
     QT_TRANSLATE_NOOP("frezka::gui::MainWindow", "Cover lock")},
    {machine::OutputFunction::ToolRelease,
     QT_TRANSLATE_NOOP("frezka::gui::MainWindow", "Tool release")},
    {machine::OutputFunction::ToolCoverOpen,
     QT_TRANSLATE_NOOP("frezka::gui::MainWindow", "Tool cover")},
};

} // namespace

// The program's modes at `line` (0: once its opening lines, up to the first motion, have run).
session::ProgramModes MainWindow::programModesAt(std::uint32_t line)
{
    const LoadedProgram &p = m_program->program();
    if (!p.text || !p.toolpath)
        return session::startModes(activeOffset());
    if (!m_modes || m_modesText != p.text.get() || m_modesSystem != activeOffset()) {
        m_modes = std::make_unique<session::ModalScanner>(p.text, activeOffset());
        m_modesText = p.text.get();
        m_modesSystem = activeOffset();
    }
    if (line == 0) {
        for (std::size_t i = 0; i < p.toolpath->size(); ++i) {
            if (p.toolpath->isMotion(i)) {
                line = p.toolpath->line(i) - 1;
                break;
            }
        }
    }
    return m_modes->at(line);
}

void MainWindow::updateStatus(const driver::MachineState &state)
{
    StatusView v;
    v.mode = state.mode;
    const bool programJob = state.jobActive && !m_consoleSession->ranLastJob();
    const bool moving = state.mode == driver::MachineMode::Running ||
                        state.mode == driver::MachineMode::Jogging ||
                        state.mode == driver::MachineMode::Homing;
    v.actualFeedMmPerMin = programJob && moving ? m_panelSpeed.speed() : 0.0;
    v.overridePercent = state.overridePercent;
    v.overrideHeldPercent = state.overrideHeldPercent();
    const std::uint32_t line = programJob ? shownLine(state) : 0;
    const LoadedProgram &p = m_program->program();
    if (p.toolpath && p.ok()) {
        const session::ProgramModes modes = programModesAt(line);
        const std::uint32_t entry = line > 0 ? p.entryOfLine(line) : gcode::Toolpath::kNone;
        if (entry != gcode::Toolpath::kNone && entry < p.toolpath->size())
            v.programmedFeedMmPerMin = p.toolpath->feedMmPerMin(entry);
        v.tool = modes.tool;
        v.spindleDirection = modes.spindle;
        v.modes = modes.gText() + QLatin1Char(' ') + modes.mText();
    }
    v.spindleOn = state.spindleOn;
    v.spindleRpm = state.spindleRpm;
    v.spindleOverridePercent = state.spindleOverridePercent;
    for (const ShownOutput &o : kShownOutputs) {
        if (machine::outputNumber(profile(), o.function) >= 0)
            v.outputs.emplace_back(tr(o.caption), state.outputOn(profile(), o.function));
    }
    v.axisCount = state.axisCount;
    for (int a = 0; a < 4; ++a)
        v.homed[std::size_t(a)] = state.axisHomed(a);
    const driver::ConnectionSettings &c = m_workflow->connection();
    v.connection = c.kind == driver::ConnectionSettings::Kind::Emulator
                       ? tr("built-in emulator")
                       : tr("%1, %2 Bd").arg(c.portName).arg(c.baud);
    m_status->show(v);
}

} // namespace frezka::gui
