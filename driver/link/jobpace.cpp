// JobPace: the job's estimates of the unit's queue and of the wire. See jobpace.h.

#include "jobpace.h"

#include "driver/link/corehost.h"
#include "driver/link/coretypes.h"
#include "driver/link/machinecore_internal.h"
#include "machine/chainparts.h"
#include "machine/leadin.h"
#include "machine/unitmodel.h"
#include "machine/unitwire.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::isMotion;
using machine::UnitOp;

void JobPace::build()
{
    const auto &cmds = m_program.commands;
    m_waitS = 0;
    m_waitExecAt = -1;
    m_vectorPrefix.assign(cmds.size() + 1, 0);
    for (std::size_t i = 0; i < cmds.size(); ++i)
        m_vectorPrefix[i + 1] = m_vectorPrefix[i] + (isMotion(cmds[i].op) ? 1 : 0);
    estimateDurations();
    // V and A are modal: each vector brakes from the last V at the last A (thousands of
    // pulses/s²) when nothing follows it.
    m_brakeS.assign(cmds.size() + 1, 0.0);
    std::int64_t speed = 0, accel = 0;
    for (std::size_t i = 0; i < cmds.size(); ++i) {
        speed = cmds[i].op == UnitOp::Speed ? cmds[i].value : speed;
        accel = cmds[i].op == UnitOp::Accel ? cmds[i].value : accel;
        m_brakeS[i + 1] =
            accel > 0 ? static_cast<double>(speed) / (1000.0 * static_cast<double>(accel)) : 0.0;
    }
    m_lastMotion.assign(cmds.size() + 1, 0);
    for (std::size_t i = 0; i < cmds.size(); ++i)
        m_lastMotion[i + 1] = isMotion(cmds[i].op) ? i + 1 : m_lastMotion[i];
    m_bytePrefix.assign(cmds.size() + 1, 0);
    for (std::size_t i = 0; i < cmds.size(); ++i) {
        const machine::UnitCommand &c = cmds[i];
        const std::size_t bytes =
            c.op > UnitOp::Spindle
                ? 0
                : encode(machine::wireCommand(c, m_program.axisCount).value_or(cmd::flag()), true)
                      .size();
        m_bytePrefix[i + 1] = m_bytePrefix[i] + static_cast<std::int64_t>(bytes);
    }
    m_tripPrefix.assign(cmds.size() + 1, 0);
    bool inRun = false; // in a run of C/B commands (one packet)
    for (std::size_t i = 0; i < cmds.size(); ++i) {
        const UnitOp op = cmds[i].op;
        const bool packetable = op == UnitOp::Vector || op == UnitOp::Brake;
        const bool wire = op <= UnitOp::Spindle;
        m_tripPrefix[i + 1] = m_tripPrefix[i] + (wire && !(packetable && inRun) ? 1 : 0);
        inRun = packetable;
    }
    findModalChanges();
}

void JobPace::findModalChanges()
{
    const auto &cmds = m_program.commands;
    m_changes.clear();
    std::size_t stretchStart = 0; // program index where the stretch before the next change began
    bool moved = false;           // motion since the last rest
    for (std::size_t i = 0; i < cmds.size(); ++i) {
        const UnitOp op = cmds[i].op;
        if (op == UnitOp::Vector || op == UnitOp::Brake) {
            moved = moved || op == UnitOp::Vector;
            continue;
        }
        if (op > UnitOp::Spindle || op == UnitOp::Line) { // a rest: the queue drains here
            moved = false;
            stretchStart = i + 1;
            continue;
        }
        if (!moved ||
            (i > 0 && cmds[i - 1].op != UnitOp::Vector && cmds[i - 1].op != UnitOp::Brake))
            continue; // before the chain's first vector, or not the change's first command
        ModalChange c;
        c.at = i;
        const std::size_t last = m_lastMotion[i] - 1; // the stretch's last vector
        const double own = m_timePrefix[last + 1] - m_timePrefix[last];
        c.stretchS = std::max(0.0, m_timePrefix[i] - m_timePrefix[stretchStart] -
                                       std::min(m_brakeS[last + 1], own));
        std::size_t j = i;
        for (; j < cmds.size() && cmds[j].op != UnitOp::Vector && cmds[j].op != UnitOp::Brake &&
               cmds[j].op <= UnitOp::Spindle && cmds[j].op != UnitOp::Line;
             ++j)
            ++c.commands;
        std::size_t k = j;
        while (k < cmds.size() && cmds[k].op == UnitOp::Brake)
            ++k;
        if (k < cmds.size() && cmds[k].op == UnitOp::Vector)
            c.nextBytes = m_bytePrefix[k + 1] - m_bytePrefix[j];
        m_changes.push_back(c);
        stretchStart = j;
    }
}

// Motion time per command under the unit's model (machine/unitmodel.h, the planner's own, exact
// for the unit when its queue does not run dry): used to judge how much motion the unit holds
// and whether the stream keeps pace with it, never for the motion itself.
void JobPace::estimateDurations()
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

// The unit just reported a full queue: it holds `capacity` vectors ending at next.
std::size_t JobPace::executingAtFull() const
{
    const std::int64_t capacity = variantInfo(m_host.config().unit.variant).queueCapacity;
    const std::size_t next = m_cursor.next;
    std::size_t k = next;
    while (k > m_cursor.exec && m_vectorPrefix[next] - m_vectorPrefix[k - 1] <= capacity)
        --k;
    return std::max(m_cursor.exec, k);
}

// The operator's override (XM) above 100 % runs the unit faster than the model: program time
// passes that much faster. Below 100 % the model's time is kept, so that the driver never thinks
// the unit holds more than it does (XM scales cruise only; the motion is at most that slower).
double JobPace::rate() const
{
    return std::max(1.0, m_host.liveState().overrideSentPercent / 100.0);
}

std::size_t JobPace::exec() const
{
    const bool valid = m_cursor.paceKey == m_cursor.exec && m_cursor.paceKeyAt == m_cursor.execAt;
    return valid ? m_cursor.paceExec : m_cursor.exec;
}

double JobPace::execAt() const
{
    const bool valid = m_cursor.paceKey == m_cursor.exec && m_cursor.paceKeyAt == m_cursor.execAt;
    return valid ? m_cursor.paceExecAt : m_cursor.execAt;
}

double JobPace::elapsedS() const
{
    const bool sameAnchor = exec() == m_waitExec && execAt() == m_waitExecAt;
    return std::max(0.0, m_host.now() - execAt() - (sameAnchor ? m_waitS : 0.0));
}

// The model runs the unit from the polled command on as if every vector were there in time;
// one that came after the model had run the unit dry made it wait (a poll at rest, then an A and
// a V before the chain's first packet: the model ran 0.13 s ahead of the unit, took it for
// holding nothing while it held 0.1 s and sent a full packet it ran dry on; property seed 34).
void JobPace::noteArrival(std::size_t oldNext, double arrivalS)
{
    if (exec() != m_waitExec || execAt() != m_waitExecAt) {
        m_waitS = 0;
        m_waitExec = exec();
        m_waitExecAt = execAt();
    }
    const std::size_t from = std::min(exec(), oldNext);
    const double drainedAt = execAt() + m_waitS + runS(from, oldNext);
    m_waitS += std::max(0.0, arrivalS - drainedAt);
}

double JobPace::runS(std::size_t from, std::size_t to) const
{
    return (m_timePrefix[to] - m_timePrefix[from]) / rate();
}

std::size_t JobPace::execEstimate() const
{
    double elapsed = elapsedS() * rate();
    std::size_t i = std::min(exec(), m_cursor.next);
    while (i < m_cursor.next && elapsed >= m_timePrefix[i + 1] - m_timePrefix[i]) {
        elapsed -= m_timePrefix[i + 1] - m_timePrefix[i];
        ++i;
    }
    return i;
}

double JobPace::bufferedS() const
{
    const std::size_t from = std::min(exec(), m_cursor.next);
    return std::max(0.0, runS(from, m_cursor.next) - elapsedS());
}

double JobPace::leadS() const
{
    const double held = bufferedS();
    const std::size_t next = m_cursor.next;
    if (held <= 0 || next >= m_lastMotion.size() || m_lastMotion[next] == 0)
        return held;
    // The last queued vector brakes for at most its own time, from the V and A it was queued
    // with (times the override): not from an A sent after it for the next one (the rapid's A113
    // was taken for the plunge's A40, its 0.17 s of braking for none: the job polled with the
    // plunge unsent, and the unit stopped before it).
    const std::size_t last = m_lastMotion[next] - 1;
    const double own = runS(last, last + 1);
    return std::max(0.0, held - std::min(m_brakeS[last + 1] * rate(), own));
}

int JobPace::maxPacket() const
{
    const int queue = variantInfo(m_host.config().unit.variant).queueCapacity - 1;
    const int wanted =
        m_host.options().maxPacketCommands > 0 ? m_host.options().maxPacketCommands : queue;
    return std::clamp(wanted, 1, queue);
}

// Whether the next queue-full of commands runs faster than it takes to send: then the wire sets
// the pace and the unit will run dry whatever the driver does, so every round trip not spent on
// the stream is lost.
bool JobPace::wireBoundAhead() const
{
    const std::size_t next = m_cursor.next;
    if (next >= m_program.commands.size())
        return false;
    const std::size_t span = static_cast<std::size_t>(maxPacket());
    const std::size_t end = std::min(m_program.commands.size(), next + span);
    const double motion = runS(next, end);
    const double wire =
        m_host.link().wireTime(static_cast<std::size_t>(m_bytePrefix[end] - m_bytePrefix[next]));
    // Each command that cannot travel in a packet (A, V, ...) is a round trip of its own, and so
    // is each packet between them (with packets off, every command). Bytes alone took a stretch
    // with an A and a V at nearly every vector for one with time to spare: the poller read
    // position, F and inputs at full rate while the first, 9 s long move ran, the stream got a
    // command in between, and the unit ran dry 17 times once those vectors came (seed 255,
    // 19 200 Bd at 11.5 ms).
    const double trips = m_host.options().packets
                             ? static_cast<double>(m_tripPrefix[end] - m_tripPrefix[next])
                             : static_cast<double>(end - next);
    return motion < wire + std::max(1.0, trips) * m_host.rttS();
}

int JobPace::overrideCeiling() const
{
    const std::size_t size = m_program.commands.size();
    const std::size_t span = static_cast<std::size_t>(maxPacket());
    const std::size_t from = std::min(exec(), m_cursor.next);
    const std::size_t last = std::min(size, m_cursor.next + span);
    double ratio = kOverrideMaxPercent / 100.0;
    for (std::size_t s = from; s < last && ratio > 1.0; ++s) {
        const std::size_t e = std::min(size, s + span);
        if (m_vectorPrefix[e] == m_vectorPrefix[s])
            continue;
        // XM scales cruise only: at p % the motion takes at least its 100 % time / p. The wire
        // needs the planner's steady margin (packets sized to what the unit holds bring more
        // than they cost only while t - w leaves 2 w RTT / t from kSteadyHeldS on: without it
        // the packets shrank to two vectors and the unit ran dry at 131 %).
        const double motion = m_timePrefix[e] - m_timePrefix[s];
        const double bytes =
            m_host.link().wireTime(static_cast<std::size_t>(m_bytePrefix[e] - m_bytePrefix[s]));
        // Without packets every command waits for its own reply (property seed 13 ran one-step
        // vectors at 160 % with a round trip per window, and the unit ran dry).
        // With packets, each A, V (or other command that cannot travel in one) between them is a
        // round trip of its own, and so is each run of vectors between them (property seed 320:
        // A alternating between 5 and 1142 at every one-step vector, each C alone, XM 200).
        const double trips = static_cast<double>(m_tripPrefix[e] - m_tripPrefix[s]);
        const double wire =
            m_host.options().packets
                ? bytes * (1 + 2 * m_host.rttS() / machine::detail::LinkTiming::kSteadyHeldS) +
                      std::max(1.0, trips) * m_host.rttS()
                : bytes + static_cast<double>(e - s) * m_host.rttS();
        ratio = std::min(ratio, motion / wire);
    }
    // A change inside a chain needs what the planner's pace gave it at 100 %: the stretch before
    // it must outlast its round trips and the next packet. XM shortens the stretch, not them
    // (property seed 390, XM 170: a vector slowed to V53 so that the V2447 after it and the
    // next packet arrive in time ran at 90 pulses/s, and the unit ran dry 19 times).
    const auto firstChange =
        std::lower_bound(m_changes.begin(), m_changes.end(), from,
                         [](const ModalChange &c, std::size_t index) { return c.at < index; });
    for (auto c = firstChange; c != m_changes.end() && c->at < last && ratio > 1.0; ++c) {
        const double need = (c->commands + 1) * m_host.rttS() +
                            m_host.link().wireTime(static_cast<std::size_t>(c->nextBytes));
        ratio = std::min(ratio, c->stretchS / need);
    }
    return std::clamp(static_cast<int>(std::floor(ratio * 100.0)), 100, kOverrideMaxPercent);
}

machine::LeadInLink JobPace::leadInLink() const
{
    machine::LeadInLink link;
    // The polls' measured round trip, bytes included: it stands for the framing and replies of
    // the short packets a lead-in goes in (the profile's turnaround alone, 2 ms at 19 200 Bd, let
    // property seed 235's chain start free, and it ran dry in packets of two vectors).
    link.roundTripS = m_host.rttS();
    link.secondsPerByte = m_host.link().wireTime(1000) / 1000.0;
    link.packets = m_host.options().packets;
    link.maxPacket = static_cast<std::size_t>(maxPacket());
    link.steadyHeldS = machine::detail::LinkTiming::kSteadyHeldS;
    return link;
}

machine::LeadInPrefixes JobPace::leadInPrefixes() const
{
    return {m_program.commands, 0,        m_timePrefix, m_bytePrefix,
            m_tripPrefix,       m_brakeS, m_lastMotion};
}

bool JobPace::chainStartsAt(std::size_t i) const
{
    return machine::chainStartsAt(m_program.commands, i);
}

std::size_t JobPace::firstPacketEnd(std::size_t start) const
{
    return machine::firstPacketEnd(m_program.commands, start, leadInLink());
}

double JobPace::leadInSlackS(std::size_t start, std::size_t queuedEnd) const
{
    // At 100 %, as the planner's estimate judges it: above, the override's ceiling keeps the
    // stretches the wire must feed within what it can (a hold judged at 150 % held chains that
    // ran without a stop at the ceiling, and the job took 3 % longer).
    return machine::leadInSlackS(leadInPrefixes(), leadInLink(), start, queuedEnd);
}

std::int64_t JobPace::plannedSpeedNow() const
{
    const auto &cmds = m_program.commands;
    for (std::size_t i = std::min(exec() + 1, cmds.size()); i-- > 0;) {
        if (cmds[i].op == machine::UnitOp::Speed)
            return cmds[i].value;
    }
    return 0;
}

std::int64_t JobPace::queuedAfter(double ahead) const
{
    const std::size_t next = m_cursor.next;
    const std::size_t from = std::min(exec(), next);
    const double at =
        std::min(m_timePrefix[from] + (elapsedS() + ahead) * rate(), m_timePrefix[next]);
    // The command executing at program time `at`: the last k with m_timePrefix[k] <= at.
    auto it = std::upper_bound(m_timePrefix.begin() + static_cast<std::ptrdiff_t>(from),
                               m_timePrefix.begin() + static_cast<std::ptrdiff_t>(next) + 1, at);
    const auto k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(
        static_cast<std::ptrdiff_t>(from), (it - m_timePrefix.begin()) - 1));
    return m_vectorPrefix[next] - m_vectorPrefix[std::min(k, next)];
}

// Strict request/reply lets no poll through while a packet is on the wire. Where the motion is
// slow, packets stay short so that the live position keeps its rate: best short enough for a
// packet and a poll to share one poll interval, else at most slowPacketWireS. A cap applies only
// where the short packet carries more than the time of the link cycle it costs (the packet, its
// reply, a poll, and on average the status and inputs reads), twice as much while the unit holds
// little, so the unit's queue still fills; where the wire is the bottleneck, packets fill the
// queue. Returns the first command the packet leaves out, or next for no cap.
std::size_t JobPace::slowMotionPacketEnd() const
{
    const auto &cmds = m_program.commands;
    const std::size_t next = m_cursor.next;
    const double rtt = m_host.rttS();
    const CoreOptions &options = m_host.options();
    // With half a second queued a smaller margin will do: the queue drains only slowly, and the
    // capacity limit takes over where it is lower.
    const double margin = bufferedS() >= std::max(0.5, 20 * rtt) ? 1.0 : 2.0;
    for (const double wire : {options.pollIntervalS - 2 * rtt, options.slowPacketWireS}) {
        if (wire < 0.005)
            continue;
        std::size_t e = next;
        while (e < cmds.size() && m_host.link().wireTime(static_cast<std::size_t>(
                                      m_bytePrefix[e + 1] - m_bytePrefix[next])) <= wire)
            ++e;
        const double cycle = wire + 2.75 * rtt;
        if (e > next && e < cmds.size() && runS(next, e) >= margin * cycle)
            return e;
    }
    return next;
}

} // namespace frezka::driver
