// UnitControls: MPG, spindle, outputs, feed override, raw commands. See unitcontrols.h.

#include "unitcontrols.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"
#include "protocol/commandparser.h"

#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::notNow;
using detail::refusal;

MachineState &UnitControls::state()
{
    return m_host.liveState();
}

std::optional<MachineError> UnitControls::setMpg(bool on)
{
    if (!state().features.mpg)
        return variantInfo(m_host.config().unit.variant).hasMpg
                   ? refusal(DriverCode::MpgNeedsFirmware,
                             {std::to_string(state().firmwareVersion)})
                   : refusal(DriverCode::NoMpg);
    if (state().mode != MachineMode::Idle)
        return notNow("Switching the MPG", state().mode);
    m_host.send(on ? cmd::mpgSilent() : cmd::mpgOff(), [this, on](const Outcome &o) {
        if (!m_host.unitError(o, "switching the MPG", MachineMode::Alarm)) {
            state().mpgOn = on;
            m_host.markDirty();
        }
    });
    return std::nullopt;
}

std::optional<MachineError> UnitControls::setSpindleRpm(double rpm)
{
    if (state().mode == MachineMode::Disconnected || state().mode == MachineMode::Connecting ||
        state().mode == MachineMode::LinkLost)
        return notNow("Setting the spindle", state().mode);
    const double maxRpm = m_host.config().spindle.maxRpm;
    if (rpm < 0 || rpm > maxRpm)
        return refusal(DriverCode::SpindleOutOfRange, {numberText(rpm), numberText(maxRpm)});
    const int asked = static_cast<int>(std::lround(rpm / maxRpm * 1000.0));
    const int permille = spindlePermilleAt(asked, state().spindleOverridePercent);
    Command c = cmd::spindle(permille);
    if (!variantInfo(m_host.config().unit.variant).hasSpindleAddress7)
        c = cmd::output((state().outputs & 0xFE) | (permille > 0 ? 0 : 1));
    m_host.send(c, [this, asked, permille, maxRpm](const Outcome &o) {
        if (m_host.unitError(o, "setting the spindle", MachineMode::Alarm))
            return;
        state().spindleAskedPermille = asked;
        state().spindlePermille = permille;
        state().spindleRpm = maxRpm * permille / 1000.0;
        m_host.markDirty();
    });
    return std::nullopt;
}

Command spindleSpeedCommand(CoreHost &host, int askedPermille)
{
    MachineState &state = host.liveState();
    state.spindleAskedPermille = askedPermille;
    host.markDirty();
    return cmd::spindle(spindlePermilleAt(askedPermille, state.spindleOverridePercent));
}

std::optional<MachineError> UnitControls::setSpindleOverride(int percent)
{
    if (percent < kSpindleOverrideMinPercent || percent > kSpindleOverrideMaxPercent)
        return refusal(DriverCode::SpindleOverrideRange,
                       {std::to_string(percent), std::to_string(kSpindleOverrideMinPercent),
                        std::to_string(kSpindleOverrideMaxPercent)});
    if (!variantInfo(m_host.config().unit.variant).hasSpindleAddress7)
        return refusal(DriverCode::NoSpindleOverride);
    if (state().mode == MachineMode::Disconnected || state().mode == MachineMode::Connecting ||
        state().mode == MachineMode::LinkLost)
        return notNow("Setting the spindle override", state().mode);
    state().spindleOverridePercent = percent;
    m_host.markDirty();
    // A turning spindle at once; one that stands (off, or stopped by a hold) when it starts.
    const int permille = spindlePermilleAt(state().spindleAskedPermille, percent);
    if (state().spindleOn && !state().outputsHeld && state().spindleAskedPermille > 0 &&
        permille != state().spindlePermille) {
        m_host.send(cmd::spindle(permille), [this](const Outcome &o) {
            m_host.unitError(o, "setting the spindle override", MachineMode::Alarm);
        });
    }
    return std::nullopt;
}

std::optional<MachineError> UnitControls::setOutput(int output, bool on)
{
    if (state().mode == MachineMode::Disconnected || state().mode == MachineMode::LinkLost)
        return notNow("Switching outputs", state().mode);
    const std::uint8_t bit = machine::outputPortBit(m_host.config().unit.variant, output);
    if (bit == 0)
        return refusal(DriverCode::NoSuchOutput, {std::to_string(output)});
    // Port 0 is active low: the output is on while its bit is 0.
    const auto value =
        static_cast<std::uint8_t>(on ? state().outputs & ~bit : state().outputs | bit);
    m_host.send(cmd::output(value), [this, value](const Outcome &o) {
        if (m_host.unitError(o, "switching outputs", MachineMode::Alarm))
            return;
        state().outputs = value;
        m_host.markDirty();
    });
    return std::nullopt;
}

std::optional<MachineError> UnitControls::setOverride(int percent)
{
    if (auto bad = validate(cmd::multiplier(percent), m_host.config().unit.variant))
        return refusal(DriverCode::OverrideInvalid, {}, commandCheckMessage(bad));
    if (!state().features.vlVkXmNa)
        return variantInfo(m_host.config().unit.variant).hasVlVkXmNa
                   ? refusal(DriverCode::OverrideNeedsFirmware,
                             {std::to_string(state().firmwareVersion)})
                   : refusal(DriverCode::NoOverride);
    // During a job the unit runs it only as far as the link can feed it (JobOverride::follow).
    const int sent = m_job.feedOverride().toSend(percent, m_job.active());
    m_host.send(cmd::multiplier(sent), [this, percent](const Outcome &o) {
        if (m_host.unitError(o, "setting the feed override (XM)", MachineMode::Alarm))
            return;
        state().overridePercent = percent;
        m_host.markDirty();
    });
    return std::nullopt;
}

std::optional<MachineError> UnitControls::overrideStep(bool up)
{
    // With XM the step is a new multiplier, exact, for the queued vectors and every one streamed
    // after; XU/XD (units without XM) change only the queued vectors' speeds.
    if (state().features.vlVkXmNa) {
        const double next = state().overridePercent * (up ? 17.0 : 15.0) / 16.0;
        return setOverride(std::clamp(static_cast<int>(std::lround(next)), kOverrideMinPercent,
                                      kOverrideMaxPercent));
    }
    // Without VL nothing keeps an axis under its maximum above the planned speeds.
    const double scale = m_job.feedOverride().speedScale() * (up ? 17.0 : 15.0) / 16.0;
    if (up && scale > 1.0 + 1e-9)
        return refusal(DriverCode::OverrideAboveWithoutVl);
    if (scale * 100.0 < kOverrideMinPercent)
        return std::nullopt; // at the slider's bottom already
    m_host.send(up ? cmd::exchangeUp() : cmd::exchangeDown(), [this, up, scale](const Outcome &o) {
        if (m_host.unitError(o, up ? "raising queued speeds (XU)" : "lowering queued speeds (XD)",
                             MachineMode::Alarm))
            return;
        // XU/XD change the queued vectors by 1/16 of their speed; the job streams every later V
        // scaled alike, so the whole rest of the job runs at the percentage shown.
        m_job.feedOverride().setSpeedScale(scale);
        state().overridePercent = static_cast<int>(std::lround(scale * 100.0));
        m_host.markDirty();
    });
    return std::nullopt;
}

std::optional<MachineError> UnitControls::sendRaw(const std::string &text)
{
    std::string line = text;
    while (!line.empty() && (line.back() == '\r' || line.back() == '\n' || line.back() == ' '))
        line.pop_back();
    if (line.empty())
        return refusal(DriverCode::EmptyCommand);
    if (line.front() != '!')
        line = "!0" + line;
    const ParsedCommand p = parseCommand(line, false);
    if (p.status != ParseStatus::Ok)
        return refusal(DriverCode::NotACommand, {text}, parseProblemMessage(p));
    if (auto bad =
            validate(p.command, m_host.config().unit.variant, m_host.config().unit.maxPulseRate))
        return refusal(DriverCode::NotACommand, {text}, commandCheckMessage(bad));
    const Op op = p.command.op;
    // Y+ makes the unit send reports unasked, in a form the manuals do not give, on a link where
    // every line from the unit is taken as the reply to the last command (docs/gve-protocol.md
    // §13).
    if (op == Op::MpgReporting)
        return refusal(DriverCode::MpgReportsUnsupported);
    if (m_job.active() && (op == Op::Line || op == Op::Vector || op == Op::Delete ||
                           op == Op::Keep || op == Op::Restore || op == Op::Jump ||
                           op == Op::ZeroAll || op == Op::SetCounter || op == Op::Home))
        return refusal(DriverCode::CommandDisturbsJob, {text});
    m_host.send(p.command, [this](const Outcome &o) {
        if (o.status != OutcomeStatus::Ok) {
            m_host.unitError(o, "raw command", MachineMode::LinkLost);
            return;
        }
        m_host.log("reply: " + o.raw);
    });
    return std::nullopt;
}

} // namespace frezka::driver
