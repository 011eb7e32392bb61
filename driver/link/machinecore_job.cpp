// MachineCore: job streaming (packets, back-pressure, PC-side waits) and its end.

#include "machinecore.h"

#include "driver/link/machinecore_internal.h"
#include "gcode/toolpath.h"
#include "machine/unitmodel.h"
#include "machine/unitwire.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using machine::UnitOp;

using detail::isModal;
using detail::isMotion;
using detail::lineText;

namespace {
// Motion kept in the unit beyond two round trips when a packet is sized to what it holds, s.
constexpr double kDryReserveS = 0.02;
// Below this much wire time to spare the unit runs dry whatever the packet: send a full one.
constexpr double kMinPacedWireS = 0.005;
} // namespace

// The one mapping of machine/unitwire.h (shared with the plan CLI). PC-side ops are never sent.
Command MachineCore::toCommand(const machine::UnitCommand &c) const
{
    return machine::wireCommand(c, m_program.axisCount).value_or(cmd::flag());
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
    if (!m_state.features.vlVkXmNa) {
        // Before v19 a GVE64 knows no speed modes: it always runs as VN (no direction
        // correction), and a plan in VK cannot run on it.
        auto &cmds = m_program.commands;
        const auto vk = std::find_if(cmds.begin(), cmds.end(), [](const machine::UnitCommand &c) {
            return c.op == UnitOp::SpeedModeVk;
        });
        if (vk != cmds.end()) {
            auto e = refuse(lineText(*vk) + ": the plan uses VK, which this unit's firmware (v" +
                            std::to_string(m_state.firmwareVersion) +
                            ") lacks (it needs v19); plan in VN (motion.speedMode \"vn\", or "
                            "unit.firmwareVersion in the profile)");
            m_program = {};
            return e;
        }
        const auto before = cmds.size();
        std::erase_if(cmds,
                      [](const machine::UnitCommand &c) { return c.op == UnitOp::SpeedModeVn; });
        if (cmds.size() != before)
            log("VN not sent: firmware v" + std::to_string(m_state.firmwareVersion) +
                " has no speed modes and always runs as VN");
    }
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
    m_toolLift = false;
    m_next = m_exec = m_inflightEnd = 0;
    m_vectorsAcked = 0;
    m_streamBlocked = m_queueFullSeen = m_needVerify = false;
    m_verified = 0;
    m_pathFault = m_pathGuardOff = m_linkWasLost = false;
    m_waitUntil = -1;
    m_packetLimit = maxPacket();
    m_vectorPrefix.assign(m_program.commands.size() + 1, 0);
    for (std::size_t i = 0; i < m_program.commands.size(); ++i)
        m_vectorPrefix[i + 1] = m_vectorPrefix[i] + (isMotion(m_program.commands[i].op) ? 1 : 0);
    estimateDurations();
    m_bytePrefix.assign(m_program.commands.size() + 1, 0);
    for (std::size_t i = 0; i < m_program.commands.size(); ++i) {
        const machine::UnitCommand &c = m_program.commands[i];
        const std::size_t bytes = c.op > UnitOp::Spindle ? 0 : encode(toCommand(c), true).size();
        m_bytePrefix[i + 1] = m_bytePrefix[i] + static_cast<std::int64_t>(bytes);
    }
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

// Motion time per command under the unit's model (machine/unitmodel.h, the planner's own, exact
// for the unit when its queue does not run dry): used to judge how much motion the unit holds
// and whether the stream keeps pace with it, never for the motion itself.
void MachineCore::estimateDurations()
{
    const machine::ModelResult model = machine::runUnitModel(m_program);
    m_timePrefix.assign(m_program.commands.size() + 1, 0.0);
    std::size_t vector = 0;
    for (std::size_t i = 0; i < m_program.commands.size(); ++i) {
        const machine::UnitCommand &c = m_program.commands[i];
        double t = 0;
        if (isMotion(c.op) && vector < model.vectorTimes.size())
            t = model.vectorTimes[vector++];
        else if (c.op == UnitOp::Dwell)
            t = static_cast<double>(c.value) / 1000.0;
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

// Whether the next queue-full of commands runs faster than it takes to send: then the wire sets
// the pace and the unit will run dry whatever the driver does, so every round trip not spent on
// the stream is lost.
bool MachineCore::wireBoundAhead() const
{
    if (!m_job || m_next >= m_program.commands.size())
        return false;
    const std::size_t span = static_cast<std::size_t>(maxPacket());
    const std::size_t end = std::min(m_program.commands.size(), m_next + span);
    const double motion = m_timePrefix[end] - m_timePrefix[m_next];
    const double wire =
        m_engine.wireTime(static_cast<std::size_t>(m_bytePrefix[end] - m_bytePrefix[m_next]));
    return motion < wire + m_rttS;
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

// Strict request/reply lets no poll through while a packet is on the wire. Where the motion is
// slow, packets stay short so that the live position keeps its rate: best short enough for a
// packet and a poll to share one poll interval, else at most slowPacketWireS. A cap applies only
// where the short packet carries more than the time of the link cycle it costs (the packet, its
// reply, a poll, and on average the status and inputs reads), twice as much while the unit holds
// little, so the unit's queue still fills; where the wire is the bottleneck, packets fill the
// queue. Returns the first command the packet leaves out, or m_next for no cap.
std::size_t MachineCore::slowMotionPacketEnd() const
{
    const auto &cmds = m_program.commands;
    // With half a second queued a smaller margin will do: the queue drains only slowly, and the
    // capacity limit takes over where it is lower.
    const double margin = bufferedS() >= std::max(0.5, 20 * m_rttS) ? 1.0 : 2.0;
    for (const double wire : {m_options.pollIntervalS - 2 * m_rttS, m_options.slowPacketWireS}) {
        if (wire < 0.005)
            continue;
        std::size_t e = m_next;
        while (e < cmds.size() && m_engine.wireTime(static_cast<std::size_t>(
                                      m_bytePrefix[e + 1] - m_bytePrefix[m_next])) <= wire)
            ++e;
        const double cycle = wire + 2.75 * m_rttS;
        if (e > m_next && e < cmds.size() &&
            m_timePrefix[e] - m_timePrefix[m_next] >= margin * cycle)
            return e;
    }
    return m_next;
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
    const std::size_t shortEnd = slowMotionPacketEnd();
    const bool keepShort = shortEnd > m_next;
    // The unit takes a packet at its *E: while the packet is on the wire, and its *E on the way,
    // the unit runs what it holds. Where the motion ahead keeps pace with the wire, a packet must
    // take no longer than that (each packet then brings more motion than it costs, so the unit
    // holds more after it), or the unit runs dry mid-chain and stops without braking. Where the
    // wire is the bottleneck, or the unit holds too little for any packet, it runs dry whatever
    // the driver does, and a full packet loses least. Kept in reserve: the reply's and the next
    // packet's round trips and a little more (the estimate of what the unit holds drifts between
    // polls), or half of what it holds when it holds little (a small queue, as the GVE84's 64
    // vectors: a short packet still comes in time).
    const double held = bufferedS();
    const double budget = held - std::min(2 * m_rttS + kDryReserveS, 0.5 * held);
    const bool paced = held > 0 && budget >= kMinPacedWireS && !wireBoundAhead();
    while (end < cmds.size() && static_cast<int>(packet.size()) < m_packetLimit) {
        const UnitOp op = cmds[end].op;
        if (op != UnitOp::Vector && op != UnitOp::Brake)
            break;
        if (keepShort && end >= shortEnd)
            break;
        Command c = toCommand(cmds[end]);
        const std::size_t size = encode(c, m_engine.checksums()).size();
        if (paced && !packet.empty() && m_engine.wireTime(bytes + size) > budget)
            break;
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
    if (m_next != first || m_pathFault)
        return; // superseded (abort, link loss, the path guard dropped the queue)
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
    if (m_next != index || m_pathFault)
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

// A wait of the job for the machine to stand before command `index`, then the path guard's
// exact check of the counters there, then `then` (unless the job moved on meanwhile).
void MachineCore::atRest(std::size_t index, std::function<void()> then)
{
    afterJobIdle([this, index, then = std::move(then)]() mutable {
        if (m_next != index)
            return;
        checkAtRest(index, [this, index, then = std::move(then)] {
            if (m_next == index)
                then();
        });
    });
}

void MachineCore::handlePcOp(const machine::UnitCommand &c, double now)
{
    (void)now;
    const std::size_t index = m_next;
    m_streamBlocked = true;
    switch (c.op) {
    case UnitOp::WaitIdle:
        atRest(index, [this, index] {
            acceptUpTo(index + 1);
            m_streamBlocked = false;
        });
        return;
    case UnitOp::Dwell:
        atRest(index, [this, index, ms = c.value] {
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
        atRest(index, [this, index, text] {
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
        atRest(index, [this, index] {
            acceptUpTo(index + 1);
            finishWithPosition();
        });
        return;
    case UnitOp::Probe:
        atRest(index, [this, index] { startProbe(index); });
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
        const machine::Steps4 &end = plannedBefore(m_program.commands.size());
        for (int a = 0; a < m_program.axisCount && !m_pathGuardOff; ++a) {
            if (m_state.positionSteps[a] != end[a]) {
                std::string at, want;
                for (int b = 0; b < m_program.axisCount; ++b) {
                    at += (b ? ", " : "") + std::to_string(m_state.positionSteps[b]);
                    want += (b ? ", " : "") + std::to_string(end[b]);
                }
                pathFault("the job ended with the counters at " + at +
                          " steps where the program ends at " + want);
                return;
            }
        }
        finishJob(true);
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

} // namespace frezka::driver
