// MachineCore: job streaming, progress and its re-establishment from the unit's counters.

#include "machinecore.h"

#include "gcode/toolpath.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using machine::UnitOp;

namespace {

bool isMotion(UnitOp op)
{
    return op == UnitOp::Vector || op == UnitOp::Line;
}

bool isModal(UnitOp op)
{
    switch (op) {
    case UnitOp::Brake:
    case UnitOp::Speed:
    case UnitOp::Accel:
    case UnitOp::Pause:
    case UnitOp::ShortThreshold:
    case UnitOp::SpeedModeVk:
    case UnitOp::SpeedModeVn:
        return true;
    default:
        return false;
    }
}

std::string lineText(const machine::UnitCommand &c)
{
    return c.sourceLine ? "line " + std::to_string(c.sourceLine) : "setup";
}

} // namespace

Command MachineCore::toCommand(const machine::UnitCommand &c) const
{
    const bool four = m_program.axisCount == 4;
    switch (c.op) {
    case UnitOp::Line:
        return four ? cmd::line(c.d[0], c.d[1], c.d[2], c.d[3]) : cmd::line(c.d[0], c.d[1], c.d[2]);
    case UnitOp::Vector:
        return four ? cmd::vector(c.d[0], c.d[1], c.d[2], c.d[3])
                    : cmd::vector(c.d[0], c.d[1], c.d[2]);
    case UnitOp::Brake:
        return cmd::brake(c.value);
    case UnitOp::Speed:
        return cmd::speed(c.value);
    case UnitOp::Accel:
        return cmd::accel(c.value);
    case UnitOp::Pause:
        return cmd::pause(c.value);
    case UnitOp::ShortThreshold:
        return cmd::shortThreshold(c.value);
    case UnitOp::SpeedModeVk:
        return cmd::speedModeVk();
    case UnitOp::SpeedModeVn:
        return cmd::speedModeVn();
    case UnitOp::Output:
        return cmd::output(static_cast<int>(c.value));
    case UnitOp::Spindle:
        return cmd::spindle(c.value);
    default:
        return cmd::flag(); // PC-side ops are never sent
    }
}

MachineCore::Result MachineCore::run(machine::UnitProgram program, double now)
{
    auto refuse = [](std::string text) { return MachineError{std::move(text), {}, {}, -1}; };
    if (m_state.mode != MachineMode::Idle)
        return refuse(std::string("a job can start only when the machine is idle (it is ") +
                      machineModeName(m_state.mode) + ")");
    const VariantInfo &info = variantInfo(m_config.unit.variant);
    if (program.axisCount != 3 && program.axisCount != 4)
        return refuse("the unit program has " + std::to_string(program.axisCount) + " axes");
    if (program.axisCount > info.axisCount)
        return refuse("the unit program has 4 axes but the " + std::string(info.displayName) +
                      " has 3");
    for (int a = 0; a < program.axisCount; ++a) {
        if (program.startSteps[a] != m_state.positionSteps[a])
            return refuse("the program was planned from " + std::to_string(program.startSteps[a]) +
                          " steps on axis " + "XYZA"[a] + " but the machine is at " +
                          std::to_string(m_state.positionSteps[a]) + "; plan it again from here");
    }
    m_program = std::move(program);
    for (const machine::UnitCommand &c : m_program.commands) {
        if (c.op > UnitOp::Spindle)
            continue;
        Command wire = toCommand(c);
        if (c.op == UnitOp::Spindle && !info.hasSpindleAddress7)
            wire = cmd::output(c.value ? 0xFE : 0xFF); // GVE84: the relay
        if (auto bad = validate(wire, m_config.unit.variant, m_config.unit.maxPulseRate)) {
            auto e = refuse(lineText(c) + ": " + bad.message);
            e.command = encodeBody(wire);
            m_program = {};
            return e;
        }
    }
    m_job = true;
    m_next = m_exec = m_inflightEnd = 0;
    m_vectorsAcked = 0;
    m_streamBlocked = m_queueFullSeen = m_needVerify = false;
    m_waitUntil = -1;
    m_packetLimit = maxPacket();
    m_vectorPrefix.assign(m_program.commands.size() + 1, 0);
    for (std::size_t i = 0; i < m_program.commands.size(); ++i)
        m_vectorPrefix[i + 1] = m_vectorPrefix[i] + (isMotion(m_program.commands[i].op) ? 1 : 0);
    estimateDurations();
    m_execAt = now;
    m_pollCount = 0;
    m_report = {};
    m_report.startS = now;
    m_bytesAtStart = m_engine.stats().bytesIn + m_engine.stats().bytesOut;
    m_resentAtStart = m_engine.stats().resent;
    m_recoveredAtStart = m_engine.stats().recovered;
    m_state.jobActive = true;
    m_state.commandsTotal = static_cast<std::int64_t>(m_program.commands.size());
    m_state.hold = HoldReason::None;
    m_state.holdText.clear();
    m_state.lastError.reset();
    setMode(MachineMode::Running);
    pump(now);
    return std::nullopt;
}

// The unit just reported a full queue: it holds `capacity` vectors ending at m_next.
void MachineCore::calibrateFull()
{
    const std::int64_t capacity = variantInfo(m_config.unit.variant).queueCapacity;
    std::size_t k = m_next;
    while (k > m_exec && m_vectorPrefix[m_next] - m_vectorPrefix[k - 1] <= capacity)
        --k;
    m_exec = std::max(m_exec, k);
    m_execAt = m_now;
}

std::size_t MachineCore::execEstimate() const
{
    double elapsed = m_now - m_execAt;
    std::size_t i = std::min(m_exec, m_next);
    while (i < m_next && elapsed >= m_timePrefix[i + 1] - m_timePrefix[i]) {
        elapsed -= m_timePrefix[i + 1] - m_timePrefix[i];
        ++i;
    }
    return i;
}

double MachineCore::bufferedS() const
{
    if (!m_job)
        return 0;
    const std::size_t from = std::min(m_exec, m_next);
    return std::max(0.0, m_timePrefix[m_next] - m_timePrefix[from] - (m_now - m_execAt));
}

// The largest packet: the unit's queue less one.
int MachineCore::maxPacket() const
{
    const int queue = variantInfo(m_config.unit.variant).queueCapacity - 1;
    const int wanted = m_options.maxPacketCommands > 0 ? m_options.maxPacketCommands : queue;
    return std::clamp(wanted, 1, queue);
}

int MachineCore::freeQueueEstimate() const
{
    const int capacity = variantInfo(m_config.unit.variant).queueCapacity;
    const std::int64_t queued = m_vectorsAcked - m_vectorPrefix[execEstimate()];
    return static_cast<int>(std::max<std::int64_t>(0, capacity - 1 - queued));
}

// Rough motion time per command (cruise at V, or min(V, B) for short vectors; acceleration
// ignored): used only to judge how much motion the unit holds, never for the motion itself.
void MachineCore::estimateDurations()
{
    double v = 1000, b = variantInfo(m_config.unit.variant).resetBrakeSpeed;
    std::int64_t shortSteps = 512;
    bool vk = false;
    m_timePrefix.assign(m_program.commands.size() + 1, 0.0);
    for (std::size_t i = 0; i < m_program.commands.size(); ++i) {
        const machine::UnitCommand &c = m_program.commands[i];
        double t = 0;
        switch (c.op) {
        case UnitOp::Speed:
            v = static_cast<double>(std::max<std::int64_t>(10, c.value));
            break;
        case UnitOp::Brake:
            b = static_cast<double>(std::max<std::int64_t>(10, c.value));
            break;
        case UnitOp::ShortThreshold:
            shortSteps = c.value;
            break;
        case UnitOp::SpeedModeVk:
            vk = true;
            break;
        case UnitOp::SpeedModeVn:
            vk = false;
            break;
        case UnitOp::Line:
        case UnitOp::Vector: {
            std::int64_t major = 0;
            double sq = 0;
            for (int a = 0; a < 4; ++a) {
                major = std::max<std::int64_t>(major, std::abs(c.d[a]));
                sq += a < 3 ? static_cast<double>(c.d[a]) * c.d[a] : 0.0;
            }
            const double length = vk ? std::sqrt(sq) : static_cast<double>(major);
            const double rate = major < shortSteps ? std::min(v, b) : v;
            t = length / rate;
            break;
        }
        case UnitOp::Dwell:
            t = static_cast<double>(c.value) / 1000.0;
            break;
        default:
            break;
        }
        m_timePrefix[i + 1] = m_timePrefix[i] + t;
    }
}

void MachineCore::streamStep(double now)
{
    if (m_needVerify)
        return;
    if (m_next >= m_program.commands.size()) {
        m_streamBlocked = true;
        afterJobIdle([this] { finishWithPosition(); });
        return;
    }
    const machine::UnitCommand &c = m_program.commands[m_next];
    if ((c.op == UnitOp::Vector || c.op == UnitOp::Brake) && m_options.packets) {
        sendPacket(now);
        return;
    }
    if (c.op > UnitOp::Spindle) {
        handlePcOp(c, now);
        return;
    }
    Command wire = toCommand(c);
    if (c.op == UnitOp::Spindle && !variantInfo(m_config.unit.variant).hasSpindleAddress7)
        wire = cmd::output((m_state.outputs & 0xFE) | (c.value ? 0 : 1));
    const std::size_t index = m_next;
    m_inflightEnd = m_next + 1;
    m_inFlight = [this, index](const Outcome &o) { onJobCommandOutcome(o, index, m_now); };
    m_engine.start(wire, now);
}

// Vectors still queued in the unit `ahead` seconds from now, by the duration estimates.
std::int64_t MachineCore::queuedAfter(double ahead) const
{
    const std::size_t from = std::min(m_exec, m_next);
    const double at =
        std::min(m_timePrefix[from] + (m_now - m_execAt) + ahead, m_timePrefix[m_next]);
    // The command executing at program time `at`: the last k with m_timePrefix[k] <= at.
    auto it = std::upper_bound(m_timePrefix.begin() + static_cast<std::ptrdiff_t>(from),
                               m_timePrefix.begin() + static_cast<std::ptrdiff_t>(m_next) + 1, at);
    const auto k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(
        static_cast<std::ptrdiff_t>(from), (it - m_timePrefix.begin()) - 1));
    return m_vectorPrefix[m_next] - m_vectorPrefix[std::min(k, m_next)];
}

void MachineCore::sendPacket(double now)
{
    // As many C/B commands as fit: the unit takes a packet at its *E, by when it has run part of
    // its queue for as long as the packet takes on the wire.
    const auto &cmds = m_program.commands;
    const std::int64_t capacity = variantInfo(m_config.unit.variant).queueCapacity - 1;
    std::vector<Command> packet;
    std::int64_t vectors = 0;
    std::size_t bytes = 24; // *S *S *E
    std::size_t end = m_next;
    while (end < cmds.size() && static_cast<int>(packet.size()) < m_packetLimit) {
        const UnitOp op = cmds[end].op;
        if (op != UnitOp::Vector && op != UnitOp::Brake)
            break;
        Command c = toCommand(cmds[end]);
        const std::size_t size = encode(c, m_engine.checksums()).size();
        if (op == UnitOp::Vector &&
            queuedAfter(m_engine.wireTime(bytes + size)) + vectors + 1 > capacity)
            break;
        bytes += size;
        vectors += op == UnitOp::Vector ? 1 : 0;
        packet.push_back(std::move(c));
        ++end;
    }
    if (packet.empty() ||
        (vectors == 0 && cmds[end < cmds.size() ? end : end - 1].op == UnitOp::Vector)) {
        // No room in the unit's queue by our estimate: wait until about 16 vectors have run.
        const std::size_t at = execEstimate();
        const std::size_t later = std::min(at + 16, m_next);
        m_waitUntil = now + std::clamp(m_timePrefix[later] - m_timePrefix[at], 0.002,
                                       m_options.pollIntervalS);
        m_queueFullSeen = true;
        return;
    }
    // The command index (mod 256) must tell a packet that arrived from one that did not: all its
    // lines (*S *S, the commands, *E) must not advance it by a multiple of 256.
    if ((packet.size() + 3) % 256 == 0) {
        packet.pop_back();
        --end;
    }
    const std::size_t first = m_next;
    m_inflightEnd = end;
    if (packet.size() == 1) {
        m_inFlight = [this, first](const Outcome &o) { onJobCommandOutcome(o, first, m_now); };
        m_engine.start(packet.front(), now);
        return;
    }
    const std::size_t n = packet.size();
    m_inFlight = [this, first, n](const Outcome &o) { onPacketOutcome(o, first, n, m_now); };
    ++m_report.packets;
    m_engine.startPacket(std::move(packet), now);
}

void MachineCore::acceptUpTo(std::size_t end)
{
    for (; m_next < end; ++m_next) {
        if (isMotion(m_program.commands[m_next].op)) {
            ++m_vectorsAcked;
            ++m_report.vectors;
            if (m_report.firstVectorAckS < 0)
                m_report.firstVectorAckS = m_now;
            m_report.lastVectorAckS = m_now;
        }
        ++m_report.commands;
    }
    m_state.commandsAcked = static_cast<std::int64_t>(m_next);
    m_state.vectorsAcked = m_vectorsAcked;
    m_dirty = true;
}

void MachineCore::onPacketOutcome(const Outcome &o, std::size_t first, std::size_t n, double now)
{
    if (m_next != first)
        return; // superseded (abort, link loss)
    if (o.status == OutcomeStatus::Failed) {
        m_packetLimit = std::max(4, m_packetLimit / 2);
        verifyProgress("packet outcome unknown: " + o.error);
        return;
    }
    const std::size_t accepted = std::min<std::size_t>(static_cast<std::size_t>(o.accepted), n);
    acceptUpTo(first + accepted);
    switch (o.reply.code) {
    case ReplyCode::Ok:
        m_queueFullSeen = false;
        m_packetLimit = std::min(maxPacket(), m_packetLimit + m_packetLimit / 2 + 1);
        return;
    case ReplyCode::QueueFull:
        // The queue is full right now: that calibrates the estimate of where the unit is.
        m_queueFullSeen = true;
        calibrateFull();
        // Bytes beyond the free space are wasted wire time: start smaller next time.
        m_packetLimit = std::max(16, static_cast<int>(accepted));
        (void)now;
        return;
    case ReplyCode::Syntax:   // a line damaged on the way (bad checksum) or lost
    case ReplyCode::Watchdog: // the packet came in too slowly: none of the rest ran
        m_packetLimit = std::max(4, m_packetLimit / 2);
        m_report.resent += static_cast<std::int64_t>(n - accepted);
        return;
    default:
        fail(lineText(m_program.commands[first + accepted]) + ": the unit refused '" +
                 encodeBody(toCommand(m_program.commands[first + accepted])) + "' (" +
                 std::string(replyCodeText(o.reply.code)) + ")",
             &o, MachineMode::Alarm);
        return;
    }
}

void MachineCore::onJobCommandOutcome(const Outcome &o, std::size_t index, double now)
{
    if (m_next != index)
        return;
    const machine::UnitCommand &c = m_program.commands[index];
    if (o.status == OutcomeStatus::Failed) {
        if (isMotion(c.op)) {
            verifyProgress("outcome unknown: " + o.error);
        } else {
            m_needVerify = true;
            fail(lineText(c) + ": " + o.error, &o, MachineMode::LinkLost);
        }
        return;
    }
    switch (o.reply.code) {
    case ReplyCode::Ok:
        if (c.op == UnitOp::Vector)
            m_queueFullSeen = false;
        acceptUpTo(index + 1);
        return;
    case ReplyCode::QueueFull: // C: queue full; L: queue not yet empty. Not accepted: again.
        m_queueFullSeen = c.op == UnitOp::Vector;
        m_waitUntil = now + m_options.pollIntervalS;
        return;
    default:
        fail(lineText(c) + ": the unit refused '" + encodeBody(o.commands.front()) + "' (" +
                 std::string(replyCodeText(o.reply.code)) + ")",
             &o, MachineMode::Alarm);
        return;
    }
}

void MachineCore::handlePcOp(const machine::UnitCommand &c, double now)
{
    (void)now;
    const std::size_t index = m_next;
    m_streamBlocked = true;
    switch (c.op) {
    case UnitOp::WaitIdle:
        afterJobIdle([this, index] {
            if (m_next != index)
                return;
            acceptUpTo(index + 1);
            m_streamBlocked = false;
        });
        return;
    case UnitOp::Dwell:
        afterJobIdle([this, index, ms = c.value] {
            if (m_next != index)
                return;
            acceptUpTo(index + 1);
            m_waitUntil = m_now + static_cast<double>(ms) / 1000.0;
            m_streamBlocked = false;
        });
        return;
    case UnitOp::OperatorStop: {
        const auto kind = static_cast<gcode::EventKind>(c.value);
        if (kind == gcode::EventKind::OptionalPause && !m_options.optionalStops) {
            acceptUpTo(index + 1);
            m_streamBlocked = false;
            return;
        }
        std::string text = kind == gcode::EventKind::ToolChange
                               ? "M6: change to tool " + std::to_string(c.aux)
                           : kind == gcode::EventKind::OptionalPause ? "M1: optional stop"
                                                                     : "M0: program stop";
        afterJobIdle([this, index, text] {
            if (m_next != index)
                return;
            acceptUpTo(index + 1);
            m_streamBlocked = false;
            m_holdNeedsGo = false;
            m_state.hold = HoldReason::OperatorStop;
            m_state.holdText = lineText(m_program.commands[index]) + ": " + text;
            setMode(MachineMode::Paused);
        });
        return;
    }
    case UnitOp::ProgramEnd:
        afterJobIdle([this, index] {
            if (m_next != index)
                return;
            acceptUpTo(index + 1);
            finishWithPosition();
        });
        return;
    case UnitOp::Probe:
        afterJobIdle([this, index] {
            if (m_next == index)
                startProbe(index);
        });
        return;
    default:
        m_streamBlocked = false;
        fail(lineText(c) + ": unknown unit program operation", nullptr, MachineMode::Alarm);
        return;
    }
}

// The job ran to its end: read the counters once more so that the report and the last state
// show where the machine really is.
void MachineCore::finishWithPosition()
{
    const Command pos = m_state.axisCount == 4 ? cmd::positionXYZA() : cmd::positionXYZ();
    send(pos, [this](const Outcome &o) {
        if (unitError(o, "reading the final position", MachineMode::LinkLost))
            return;
        applyPosition(o.reply);
        finishJob(true);
    });
}

// G38.x: the tool sensor probe (IN15) as an interrupt, armed for contact (G38.2/.3) or for its
// loss (G38.4/.5), then the probe move as an L. The unit brakes when the input fires; the
// counters give the trip point. The planner planned the rest of the program from the probe's
// end point, so when the probe stops short and motion follows, the job ends there (to be planned
// again from the trip point) rather than run displaced.
// Two position reads that agree: the machine stands (after RUN = 0 or an interrupt's brake).
void MachineCore::whenStill(std::function<void()> then)
{
    const Command pos = m_state.axisCount == 4 ? cmd::positionXYZA() : cmd::positionXYZ();
    send(pos, [this, pos, then](const Outcome &first) {
        if (unitError(first, "reading the position", MachineMode::Alarm))
            return;
        send(pos, [this, then, a = first.reply.values](const Outcome &second) {
            if (unitError(second, "reading the position", MachineMode::Alarm))
                return;
            applyPosition(second.reply);
            if (second.reply.values == a)
                then();
            else
                whenStill(then);
        });
    });
}

void MachineCore::startProbe(std::size_t index)
{
    const machine::UnitCommand c = m_program.commands[index];
    const auto kind = static_cast<gcode::ProbeKind>(c.aux);
    const bool toward =
        kind == gcode::ProbeKind::TowardErrorIfNoContact || kind == gcode::ProbeKind::Toward;
    const bool mustTrip = kind == gcode::ProbeKind::TowardErrorIfNoContact ||
                          kind == gcode::ProbeKind::AwayErrorIfNoLoss;
    const machine::EepromConfig &ee = m_config.eeprom;
    const std::uint8_t contactHigh = ee.polarityHigh & 0x80; // IN15 level that means contact
    const auto armPolarity = static_cast<std::uint8_t>(
        (ee.polarityHigh & 0x7F) | (toward ? contactHigh : (contactHigh ^ 0x80)));
    send(cmd::input2(), [this, index, armPolarity](const Outcome &o) {
        if (unitError(o, "reading the probe input", MachineMode::Alarm))
            return;
        if ((*o.reply.hexValue() & 0x80) == (armPolarity & 0x80)) {
            m_steps.clear();
            finishJob(false);
            fail(lineText(m_program.commands[index]) +
                     ": the probe input is already in the state the probe move waits for",
                 &o, MachineMode::Alarm);
        }
    });
    send(cmd::statusWrite(1, ee.interruptEnableHigh | 0x80),
         [this](const Outcome &o) { unitError(o, "arming the probe input", MachineMode::Alarm); });
    send(cmd::statusWrite(3, armPolarity),
         [this](const Outcome &o) { unitError(o, "arming the probe input", MachineMode::Alarm); });
    send(toCommand({machine::UnitOp::Line, c.d}), [this, index, mustTrip](const Outcome &o) {
        if (unitError(o, "probe move", MachineMode::Alarm))
            return;
        m_haltExpected = true;
        afterStopOrInterrupt([this, index, mustTrip] {
            whenStill([this, index, mustTrip] { endProbe(index, mustTrip); });
        });
    });
}

void MachineCore::endProbe(std::size_t index, bool mustTrip)
{
    const Command pos = m_state.axisCount == 4 ? cmd::positionXYZA() : cmd::positionXYZ();
    send(cmd::statusRead(5), [this](const Outcome &o) {
        if (!unitError(o, "reading the probe result", MachineMode::Alarm))
            m_state.probeTripped = (*o.reply.hexValue() & 0x80) != 0;
    });
    send(pos, [this](const Outcome &o) {
        if (!unitError(o, "reading the probe position", MachineMode::Alarm)) {
            applyPosition(o.reply);
            m_state.probeSteps = m_state.positionSteps;
        }
    });
    // D drops what is left of the probe move and clears INTA and the cause bits.
    send(cmd::deleteQueue(), [this](const Outcome &o) { unitError(o, "D", MachineMode::Alarm); });
    const machine::EepromConfig &ee = m_config.eeprom;
    send(cmd::statusWrite(1, ee.interruptEnableHigh), [](const Outcome &) {});
    send(cmd::statusWrite(3, ee.polarityHigh), [this, index, mustTrip](const Outcome &o) {
        m_haltExpected = false;
        if (unitError(o, "disarming the probe input", MachineMode::Alarm))
            return;
        m_state.inta = false;
        const machine::UnitCommand &c = m_program.commands[index];
        bool atEnd = true;
        for (int a = 0; a < m_program.axisCount; ++a)
            atEnd = atEnd && m_state.positionSteps[a] == c.endSteps[a];
        if (!m_state.probeTripped && mustTrip) {
            m_state.hold = HoldReason::ProbeFailed;
            finishJob(false);
            fail(lineText(c) + ": the probe move ended without the probe tripping", nullptr,
                 MachineMode::Alarm);
            return;
        }
        const bool motionFollows = std::any_of(
            m_program.commands.begin() + static_cast<std::ptrdiff_t>(index) + 1,
            m_program.commands.end(), [](const machine::UnitCommand &u) {
                return u.op == UnitOp::Vector || u.op == UnitOp::Line || u.op == UnitOp::Probe;
            });
        if (!atEnd && motionFollows) {
            finishJob(false);
            fail(lineText(c) + ": the probe tripped at " + std::to_string(m_state.probeSteps[0]) +
                     ", " + std::to_string(m_state.probeSteps[1]) + ", " +
                     std::to_string(m_state.probeSteps[2]) +
                     " steps; the rest of the program was planned from the probe's end point: "
                     "plan it again from here",
                 nullptr, MachineMode::Alarm);
            return;
        }
        acceptUpTo(index + 1);
        m_streamBlocked = false;
    });
}

void MachineCore::finishJob(bool ok)
{
    if (!m_job)
        return;
    m_job = false;
    m_streamBlocked = false;
    m_report.finished = ok;
    m_report.endS = m_now;
    m_report.linkBytes = m_engine.stats().bytesIn + m_engine.stats().bytesOut - m_bytesAtStart;
    m_report.resent += m_engine.stats().resent - m_resentAtStart;
    m_report.recovered = m_engine.stats().recovered - m_recoveredAtStart;
    m_state.jobActive = false;
    m_state.progress = ok ? 1.0 : m_state.progress;
    m_state.etaS = ok ? 0 : -1;
    m_dirty = true;
    if (m_state.mode == MachineMode::Running)
        setMode(MachineMode::Idle);
    log(ok ? "job finished" : "job ended");
    publish(); // the final state before the news that the job ended
    if (onJobFinished)
        onJobFinished(ok);
}

// The executing command from the polled position: the first motion command from m_exec on
// whose box (from its start to its end position) holds the position and which has not ended.
void MachineCore::locateExecuting()
{
    const auto &cmds = m_program.commands;
    const int axes = m_program.axisCount;
    const auto &pos = m_state.positionSteps;
    std::size_t i = m_exec;
    const std::size_t limit = std::min(m_next, cmds.size());
    for (int guard = 0; i < limit && guard < 100000; ++i, ++guard) {
        if (!isMotion(cmds[i].op))
            continue;
        const machine::Steps4 &end = cmds[i].endSteps;
        bool atEnd = true;
        bool inside = true;
        for (int a = 0; a < axes; ++a) {
            const std::int64_t start = end[a] - cmds[i].d[a];
            atEnd = atEnd && pos[a] == end[a];
            inside =
                inside && pos[a] >= std::min(start, end[a]) && pos[a] <= std::max(start, end[a]);
        }
        if (inside && !atEnd)
            break;
    }
    m_exec = i;
    const std::size_t shown = std::min(i, cmds.empty() ? 0 : cmds.size() - 1);
    m_state.sourceLine = cmds.empty() ? 0 : cmds[shown].sourceLine;
    m_state.progress = cmds.empty() ? 0 : static_cast<double>(i) / static_cast<double>(cmds.size());
    const double elapsed = m_now - m_report.startS;
    m_state.etaS =
        i > 0 ? elapsed * static_cast<double>(cmds.size() - i) / static_cast<double>(i) : -1;
}

void MachineCore::verifyProgress(const std::string &why)
{
    log("re-establishing job progress from the unit's counters: " + why);
    ++m_report.verified;
    m_needVerify = true;
    m_streamBlocked = true;
    readStillPosition();
}

// Waits for RUN = 0, then reads the counters twice: the machine stands only when both reads
// agree (a late reply on a noisy line must not pass for the final position).
void MachineCore::readStillPosition()
{
    afterIdle([this] {
        const Command pos = m_state.axisCount == 4 ? cmd::positionXYZA() : cmd::positionXYZ();
        send(pos, [this, pos](const Outcome &first) {
            if (unitError(first, "reading the position", MachineMode::LinkLost))
                return;
            send(pos, [this, a = first.reply.values](const Outcome &second) {
                if (unitError(second, "reading the position", MachineMode::LinkLost))
                    return;
                if (second.reply.values != a) {
                    readStillPosition(); // still moving: wait again
                    return;
                }
                applyPosition(second.reply);
                matchProgress();
            });
        });
    });
}

void MachineCore::matchProgress()
{
    // The unit ran everything it accepted; it accepted a prefix of the program. Find the
    // prefix lengths j in [m_next, m_inflightEnd] whose end position equals the counters.
    const auto &cmds = m_program.commands;
    const int axes = m_program.axisCount;
    const std::size_t hi = std::min(std::max(m_inflightEnd, m_next), cmds.size());
    std::size_t lo = m_next;
    auto endOf = [&](std::size_t j) -> const machine::Steps4 & {
        return j == 0 ? m_program.startSteps : cmds[j - 1].endSteps;
    };
    std::vector<std::size_t> matches;
    for (std::size_t j = lo; j <= hi; ++j) {
        bool same = true;
        for (int a = 0; a < axes; ++a)
            same = same && endOf(j)[a] == m_state.positionSteps[a];
        if (same)
            matches.push_back(j);
    }
    // Several j with the same end position differ only by modal commands (B) or zero moves:
    // taking the first is exact as long as they are contiguous (modal commands are re-sent).
    bool contiguous = !matches.empty();
    for (std::size_t k = 1; k < matches.size(); ++k)
        contiguous = contiguous && (matches[k] == matches[k - 1] + 1 ||
                                    m_vectorPrefix[matches[k]] == m_vectorPrefix[matches[0]]);
    if (!contiguous) {
        fail(matches.empty()
                 ? "the unit's counters match no point the job has reached; the job cannot "
                   "resume exactly (re-home and start it again)"
                 : "the unit's counters match several points of the job; cannot tell how far "
                   "it got (abort the job)",
             nullptr, MachineMode::Alarm);
        return;
    }
    const std::size_t j = matches.front();
    log("progress re-established at command " + std::to_string(j) + " of " +
        std::to_string(cmds.size()));
    acceptUpTo(j);
    m_inflightEnd = j;
    m_exec = std::min(m_exec, j);
    resendModals([this] {
        m_needVerify = false;
        m_streamBlocked = false;
        m_queueFullSeen = false;
    });
}

void MachineCore::resendModals(std::function<void()> then)
{
    // The last value of each modal command before m_next, sent again in program order.
    std::vector<std::size_t> last;
    std::array<bool, 16> seen{};
    for (std::size_t i = m_next; i-- > 0;) {
        const UnitOp op = m_program.commands[i].op;
        if (!isModal(op))
            continue;
        const auto slot =
            static_cast<std::size_t>(op == UnitOp::SpeedModeVn ? UnitOp::SpeedModeVk : op);
        if (seen[slot])
            continue;
        seen[slot] = true;
        last.push_back(i);
    }
    std::reverse(last.begin(), last.end());
    for (std::size_t i : last) {
        send(toCommand(m_program.commands[i]), [this](const Outcome &o) {
            unitError(o, "re-sending the job's speed settings", MachineMode::Alarm);
        });
    }
    send(cmd::flag(), [this, then = std::move(then)](const Outcome &o) {
        if (unitError(o, "status", MachineMode::Alarm))
            return;
        applyFlags(*o.reply.hexValue(), m_now);
        then();
    });
}

} // namespace frezka::driver
