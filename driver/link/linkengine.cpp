// LinkEngine: strict request/reply transactions on the unit's line. See linkengine.h.

#include "linkengine.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;

namespace {
// Longest reply we allow time for: a P4 reply with checksum is ~56 bytes.
constexpr std::size_t kLongestReplyBytes = 64;
} // namespace

LinkEngine::LinkEngine(LinkOptions options)
    : m_options(options)
{
    setBaud(options.baud);
}

bool LinkEngine::exact() const
{
    return m_packet || mustArriveOnce(m_commands.front().op);
}

double LinkEngine::wireTime(std::size_t bytes) const
{
    return static_cast<double>(bytes) * 10.0 / m_options.baud;
}

double LinkEngine::replyAllowanceS() const
{
    return 2 * std::max(m_options.latencyS, kAdapterLatencyMaxS) + m_options.replyMarginS;
}

const Command &LinkEngine::mainCommand() const
{
    static const Command kPacketEnd = cmd::packetEnd(0);
    return m_packet ? kPacketEnd : m_commands.front();
}

std::string LinkEngine::describe() const
{
    if (!m_packet)
        return "'" + encodeBody(m_commands.front()) + "'";
    return "packet of " + std::to_string(m_commands.size()) + " commands starting '" +
           encodeBody(m_commands.front()) + "'";
}

std::string LinkEngine::commandArg() const
{
    const std::string first = "'" + encodeBody(m_commands.front()) + "'";
    return m_packet ? first + " (+" + std::to_string(m_commands.size() - 1) + ")" : first;
}

// Time from now until a reply to `c` is overdue. Counted from when our bytes have left (they may
// queue behind earlier ones), plus the longest reply, plus the class's allowance.
double LinkEngine::timeoutFor(const Command &c, std::size_t bytes, double now)
{
    const double start = std::max(now, m_txDoneAt);
    m_txDoneAt = start + wireTime(bytes);
    const double wire = (m_txDoneAt - now) + wireTime(kLongestReplyBytes);
    switch (c.op) {
    case Op::Halt:
        return wire + m_options.haltTimeoutS;
    case Op::Home:
        return wire + m_options.homeTimeoutS;
    case Op::Jump: // the unit is deaf for about 2 s after J and does not answer it
        return wire + replyAllowanceS() + 2.5;
    default:
        return wire + replyAllowanceS();
    }
}

int LinkEngine::indexAfter() const
{
    const int before = m_indexBefore.value_or(0);
    if (m_packet)
        return (before + packetIndexAdvance(static_cast<int>(m_commands.size())) +
                (m_options.doublePacketStart ? 1 : 0)) %
               256;
    return advancesIndex(m_commands.front().op) ? (before + 1) % 256 : before;
}

void LinkEngine::log(LinkLogKind kind, const std::string &text)
{
    if (onLog)
        onLog(kind, text);
}

std::string LinkEngine::takeOutput()
{
    std::string out;
    out.swap(m_out);
    return out;
}

Command LinkEngine::routed(Command c) const
{
    if (c.address == 0)
        c.address = static_cast<std::uint8_t>(m_options.unitAddress);
    return c;
}

void LinkEngine::start(const Command &command, double now, std::uint64_t tag)
{
    m_commands = {routed(command)};
    m_packet = false;
    m_syncing = false;
    m_tag = tag;
    m_attempts = m_resent = m_recovered = 0;
    beginOrWait(now);
}

void LinkEngine::startPacket(std::vector<Command> commands, double now, std::uint64_t tag)
{
    for (Command &c : commands)
        c = routed(std::move(c));
    m_commands = std::move(commands);
    m_packet = true;
    m_syncing = false;
    m_tag = tag;
    m_attempts = m_resent = m_recovered = 0;
    beginOrWait(now);
}

void LinkEngine::syncIndex(double now, std::uint64_t tag)
{
    m_commands = {routed(cmd::index())};
    m_packet = false;
    m_syncing = true;
    m_tag = tag;
    m_attempts = m_resent = m_recovered = 0;
    beginOrWait(now);
}

void LinkEngine::beginOrWait(double now)
{
    if (m_options.sharedLine) {
        m_state = State::AwaitGrant;
        m_deadline = kNoDeadline;
        return;
    }
    grantLine(now);
}

void LinkEngine::grantLine(double now)
{
    if (!m_syncing) {
        beginTransaction(now);
        return;
    }
    m_indexBefore = m_index;
    ++m_stats.transactions;
    transmitMain(now);
}

bool LinkEngine::lateWatchdog(const Line &line) const
{
    if (line.overlong || m_state == State::Idle || m_state == State::AwaitGrant)
        return false;
    const ReplyResult r =
        decodeReply(line.text, m_checksums ? ChecksumMode::On : ChecksumMode::Off);
    return r.reply && r.reply->code == ReplyCode::Watchdog && r.reply->values.empty();
}

void LinkEngine::beginTransaction(double now)
{
    ++m_stats.transactions;
    m_watchdogDue = false;
    m_ranSingly = false;
    m_lastRepeat.clear();
    m_packetGap = false;
    m_indexBefore = m_index;
    if (m_index || !exact()) {
        transmitMain(now);
        return;
    }
    // Without the unit's index a lost reply could not be resolved: learn it first (routine, not a
    // recovery: logged as sent).
    m_presync = true;
    sendAux(cmd::index(), State::AwaitIndex, now, LinkLogKind::Sent);
}

void LinkEngine::transmitMain(double now)
{
    m_doubtfulSeen = false;
    m_wire = m_packet ? encodePacket(m_commands, m_checksums) : encode(m_commands[0], m_checksums);
    if (m_packet && m_options.doublePacketStart)
        m_wire = encode(routed(cmd::packetStart()), m_checksums) + m_wire;
    m_out += m_wire;
    m_stats.bytesOut += static_cast<std::int64_t>(m_wire.size());
    log(LinkLogKind::Sent, m_packet ? describe() : encodeBody(m_commands[0]));
    m_state = State::AwaitReply;
    m_deadline = now + timeoutFor(mainCommand(), m_wire.size(), now);
}

void LinkEngine::sendAux(const Command &command, State next, double now, LinkLogKind kind)
{
    const Command c = routed(command);
    const std::string bytes = encode(c, m_checksums);
    m_out += bytes;
    m_stats.bytesOut += static_cast<std::int64_t>(bytes.size());
    log(kind, encodeBody(c));
    m_state = next;
    m_deadline = now + timeoutFor(c, bytes.size(), now);
}

void LinkEngine::receive(std::string_view bytes, double now)
{
    m_stats.bytesIn += static_cast<std::int64_t>(bytes.size());
    m_decoder.feed(bytes);
    while (auto line = m_decoder.nextLine())
        handleLine(*line, now);
}

void LinkEngine::handleLine(const Line &line, double now)
{
    if (line.text.empty() && !line.overlong) {
        ++m_stats.noiseLines; // a stray CR: nothing to decode, nothing lost
        log(LinkLogKind::Noise, "empty line");
        return;
    }
    if (m_watchdogDue && lateWatchdog(line)) {
        // The unit's watchdog answer (code 2) to the command whose reply we stopped waiting
        // for: it was cut short, and the unit answers that only once its watchdog runs out,
        // which may be after our reply allowance. Taken for a query's answer it would make us
        // ask again with that query's own answer still on its way, and every reply after it
        // one late (property seed 32: a packet's '>' answered with the count of '@').
        m_watchdogDue = false;
        ++m_stats.noiseLines;
        log(LinkLogKind::Noise, line.text + " (the watchdog's late answer, dropped)");
        return;
    }
    switch (m_state) {
    case State::Idle:
    case State::AwaitGrant:
    case State::Settle:
        ++m_stats.noiseLines;
        log(LinkLogKind::Noise, line.text);
        return;
    case State::AwaitReply:
        onMainReply(line, now);
        return;
    case State::AwaitIndex:
        onIndexReply(line, now);
        return;
    case State::AwaitRepeat:
        onRepeatReply(line, now);
        return;
    }
}

std::optional<Reply> LinkEngine::decodeFor(const Command &c, const std::string &line,
                                           std::string &err)
{
    // The reply to %+ already carries a checksum, the reply to %- does not (§2.1); while the
    // unit's state is in doubt, accept either.
    const bool switching = c.op == Op::ChecksumOn || c.op == Op::ChecksumOff;
    const ChecksumMode mode = switching     ? ChecksumMode::Auto
                              : m_checksums ? ChecksumMode::On
                                            : ChecksumMode::Off;
    const ReplyResult res = decodeReply(line, mode);
    if (res.error) {
        err = res.error->message;
        return std::nullopt;
    }
    if (auto shape = checkReplyShape(c, *res.reply, line)) {
        err = shape->message;
        return std::nullopt;
    }
    if (c.op == Op::ChecksumOn && res.reply->ok())
        m_checksums = true;
    if (c.op == Op::ChecksumOff && res.reply->ok())
        m_checksums = false;
    return res.reply;
}

bool LinkEngine::answeredSingly(const Line &line) const
{
    if (line.overlong)
        return false;
    const ReplyResult r =
        decodeReply(line.text, m_checksums ? ChecksumMode::On : ChecksumMode::Off);
    return r.reply && r.reply->values.empty() && r.reply->code != ReplyCode::Syntax &&
           r.reply->code != ReplyCode::Watchdog;
}

void LinkEngine::onMainReply(const Line &line, double now)
{
    if (m_packet && (m_ranSingly || answeredSingly(line))) {
        // A packet answers once, with its count (a plain 4 or 2 may be a damaged *S's). A plain
        // 0 or 1 (8 or 9 while held) is a C or B answered as a command of its own: both *S were
        // damaged and the unit queued the lines it had room for, the others not (GVE64 link
        // seed 27 of the overfeed raster: a plain 9 taken for the packet's "none accepted", the
        // vectors queued twice over). Nothing it says settles what ran: wait for the rest of
        // its answers to pass, then fail the packet (onTime) for the counters to settle it.
        ++m_stats.noiseLines;
        log(LinkLogKind::Noise, line.text);
        if (!m_ranSingly)
            log(LinkLogKind::Recovery,
                describe() + ": a line answered on its own: the packet's start was lost");
        m_ranSingly = true;
        return;
    }
    std::string err;
    const auto reply = line.overlong ? std::nullopt : decodeFor(mainCommand(), line.text, err);
    log(LinkLogKind::Received, line.text);
    if (!reply) {
        ++m_stats.garbledLines;
        m_lastRaw = line.text;
        if (m_packet && now < m_deadline) {
            // Noise while a packet is on its way: its own reply may still come.
            m_doubtfulSeen = true;
            log(LinkLogKind::Recovery, describe() + ": garbled line '" + line.text + "', waiting");
            return;
        }
        recover("garbled reply", line.text, err.empty() ? "" : ": " + err, now);
        return;
    }
    // Possibly damaged on the way in (code 4 = bad checksum) or cut short (code 2): the index
    // tells whether the unit took it as a command.
    // A packet's "4,k" is definitive (a line was damaged: k ran, the rest did not); a plain "4"
    // or "2" may belong to a damaged *E or to an earlier broken line.
    const bool counted = m_packet && !reply->values.empty();
    const bool doubtful = (reply->code == ReplyCode::Syntax && m_checksums && !counted) ||
                          reply->code == ReplyCode::Watchdog;
    if (doubtful && m_packet && now < m_deadline) {
        // A plain "4" may answer a damaged first *S while the packet itself still runs and
        // answers with its count: wait for that until the packet's deadline.
        m_doubtfulSeen = true;
        m_lastRaw = line.text;
        log(LinkLogKind::Recovery, describe() + ": reply '" + line.text + "', waiting for more");
        return;
    }
    if (doubtful && !m_syncing && (m_indexBefore || !exact())) {
        m_lastRaw = line.text;
        recover("doubtful reply", line.text, " (" + std::string(replyCodeText(reply->code)) + ")",
                now);
        return;
    }
    finishOk(*reply, line.text);
}

void LinkEngine::onTime(double now)
{
    if (now < m_deadline)
        return;
    switch (m_state) {
    case State::Idle:
    case State::AwaitGrant:
        m_deadline = kNoDeadline;
        return;
    case State::AwaitReply:
        if (m_ranSingly) {
            m_index.reset(); // every line that arrived whole advanced it: learn it again
            finishFailed(describe() + ": its lines were answered one by one (both *S damaged); "
                                      "what the unit queued is not known",
                         LinkFailure::IndexUnknown, {commandArg()});
            return;
        }
        ++m_stats.timeouts;
        m_watchdogDue = true;
        if (!m_decoder.pending().empty())
            m_lastRaw = m_decoder.pending();
        if (m_decoder.pending().empty())
            recover("no reply", "", "", now);
        else
            recover("incomplete reply", m_decoder.pending(), "", now);
        return;
    case State::AwaitIndex:
    case State::AwaitRepeat:
        ++m_stats.timeouts;
        retryAux("no reply to recovery query", "", now);
        return;
    case State::Settle:
        m_decoder.clear();
        if (m_presync) {
            sendAux(cmd::index(), State::AwaitIndex, now);
        } else if (m_syncing) {
            transmitMain(now);
        } else if (!exact()) {
            // Harmless to repeat: send it again. It may have arrived before, so the unit's
            // index is no longer known (learnt again before the next exact command).
            ++m_resent;
            ++m_stats.resent;
            m_index.reset();
            m_indexBefore.reset();
            transmitMain(now);
        } else
            sendAux(cmd::index(), State::AwaitIndex, now);
        return;
    }
}

void LinkEngine::finishOk(const Reply &r, const std::string &raw)
{
    const int after = indexAfter();
    Outcome o;
    o.status = OutcomeStatus::Ok;
    o.commands = std::move(m_commands);
    o.packet = m_packet;
    o.reply = r;
    o.raw = raw;
    o.resent = m_resent;
    o.recovered = m_recovered;
    o.tag = m_tag;
    if (m_syncing) {
        m_index = static_cast<int>(r.decimal().value_or(0));
    } else if (m_packet) {
        o.accepted = r.ok() ? static_cast<int>(o.commands.size())
                            : static_cast<int>(r.decimal().value_or(0));
        // The index after a failed packet depends on where it stopped: learn it next time. So
        // it does after a packet that drew a complaint or noise before its count: a damaged *S
        // line answered 4 and did not count, or a damaged line may have been taken as some
        // other command; guessing wrong would later make a sent vector look unsent.
        m_index =
            r.ok() && m_indexBefore && !m_doubtfulSeen ? std::optional<int>(after) : std::nullopt;
    } else if (m_indexBefore && advancesIndex(o.commands.front().op)) {
        m_index = after;
    }
    if (o.commands.front().op == Op::Jump)
        m_index = 0;
    const bool advances = m_packet || advancesIndex(o.commands.front().op);
    const bool doubtful = (r.code == ReplyCode::Syntax && !(m_packet && !r.values.empty())) ||
                          r.code == ReplyCode::Watchdog;
    if (o.commands.front().op == Op::Jump || (advances && doubtful))
        m_unitLastReply.reset();
    else if (advances && !m_syncing)
        m_unitLastReply = raw;
    finish();
    if (onOutcome)
        onOutcome(o);
}

void LinkEngine::finishFailed(const std::string &why, LinkFailure failure,
                              std::vector<std::string> failureArgs)
{
    Outcome o;
    o.status = OutcomeStatus::Failed;
    o.failure = failure;
    o.failureArgs = std::move(failureArgs);
    o.commands = std::move(m_commands);
    o.packet = m_packet;
    o.raw = m_lastRaw;
    o.error = why;
    o.resent = m_resent;
    o.recovered = m_recovered;
    o.tag = m_tag;
    log(LinkLogKind::Error, why);
    m_unitLastReply.reset(); // it may have run, with a reply we do not know
    m_packetGap = false;
    finish();
    if (onOutcome)
        onOutcome(o);
}

void LinkEngine::finish()
{
    m_presync = false;
    m_state = State::Idle;
    m_deadline = kNoDeadline;
    m_commands.clear();
    m_lastRaw.clear();
}

void LinkEngine::reset()
{
    m_txDoneAt = 0;
    finish();
    m_decoder.clear();
    m_out.clear();
    m_index.reset();
}

} // namespace frezka::driver
