// LinkEngine: the recovery of a lost or doubtful reply with '@' and '>' (§8). See linkengine.h.

#include "linkengine.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;

void LinkEngine::onIndexReply(const Line &line, double now)
{
    std::string err;
    const auto reply = line.overlong ? std::nullopt : decodeFor(cmd::index(), line.text, err);
    if (!reply || !reply->ok()) {
        ++m_stats.garbledLines;
        retryAux("garbled reply to '@'", line.text, now);
        return;
    }
    const int unitIndex = static_cast<int>(*reply->decimal());
    if (m_presync) {
        log(LinkLogKind::Received, line.text);
        m_presync = false;
        m_index = m_indexBefore = unitIndex;
        transmitMain(now);
        return;
    }
    log(LinkLogKind::Recovery, "index " + std::to_string(unitIndex));
    if (!m_indexBefore) {
        // We did not know the index before this transaction: we cannot tell whether it
        // arrived. Learn it and report the transaction failed (the caller decides).
        m_index = unitIndex;
        finishFailed(describe() + ": reply lost and the unit's command index was unknown",
                     LinkFailure::IndexUnknown, {commandArg()});
        return;
    }
    if (unitIndex == indexAfter()) {
        m_index = unitIndex;
        sendAux(cmd::repeat(), State::AwaitRepeat, now);
        return;
    }
    if (unitIndex == *m_indexBefore) {
        ++m_resent;
        ++m_stats.resent;
        log(LinkLogKind::Recovery, "not received, sending again: " + describe());
        transmitMain(now);
        return;
    }
    const int gap = (unitIndex - *m_indexBefore + 256) % 256;
    if (m_packet && m_checksums && m_unitLastReply &&
        gap < (indexAfter() - *m_indexBefore + 256) % 256) {
        // Part of the packet's lines counted: a line was damaged on the way. If its *E arrived,
        // the packet ran up to the damaged line and '>' brings its count; if not, the '@' has
        // abandoned it, nothing of it ran, and '>' brings the unit's reply before it (§2.2,
        // docs/emulator.md). Which of the two, the reply tells when the earlier one is known.
        m_index = unitIndex;
        m_packetGap = true;
        sendAux(cmd::repeat(), State::AwaitRepeat, now);
        return;
    }
    m_index = unitIndex;
    finishFailed(describe() + ": the unit's command index is " + std::to_string(unitIndex) +
                     ", expected " + std::to_string(*m_indexBefore) + " or " +
                     std::to_string(indexAfter()),
                 LinkFailure::IndexUnexpected,
                 {commandArg(), std::to_string(unitIndex), std::to_string(*m_indexBefore),
                  std::to_string(indexAfter())});
}

void LinkEngine::onRepeatReply(const Line &line, double now)
{
    std::string err;
    if (m_packetGap && !line.overlong && line.text == m_unitLastReply) {
        // The reply before the packet, whatever its shape (a poll's, say): see packetGapAnswer.
        if (const ReplyResult r = decodeReply(line.text, ChecksumMode::On); r.reply) {
            packetGapAnswer(*r.reply, line.text, now);
            return;
        }
    }
    const auto reply = line.overlong ? std::nullopt : decodeFor(mainCommand(), line.text, err);
    if (!reply) {
        ++m_stats.garbledLines;
        retryAux("garbled repeated reply", line.text, now);
        return;
    }
    if (m_packetGap && packetGapAnswer(*reply, line.text, now))
        return;
    // '>' itself may arrive damaged: the unit then complains about it (4 = bad checksum, 2 = cut
    // short), which is not the reply it was asked to repeat. A packet that arrived whole (the
    // index said so) always answers with its count; a single command's doubtful answer counts
    // only when '>' brings it twice.
    const bool counted = m_packet && !reply->values.empty();
    const bool doubtful = (reply->code == ReplyCode::Syntax && m_checksums && !counted) ||
                          reply->code == ReplyCode::Watchdog;
    if (doubtful && (m_packet || line.text != m_lastRepeat)) {
        m_lastRepeat = line.text;
        retryAux("doubtful repeated reply", line.text, now);
        return;
    }
    ++m_recovered;
    ++m_stats.recovered;
    finishOk(*reply, line.text);
}

// The answer to '>' after a packet only part of whose lines counted (onIndexReply). Returns
// false to judge it as any repeated reply.
bool LinkEngine::packetGapAnswer(const Reply &reply, const std::string &text, double now)
{
    const auto n = static_cast<std::int64_t>(m_commands.size());
    // What the packet itself can answer with a line missing: its count short of n with an error
    // code, or all n when the missing line was the spare *S.
    const auto couldBeOurs = [n](const Reply &r) {
        const auto k = r.values.size() == 1 ? r.decimal() : std::nullopt;
        return k && (r.ok() ? *k == n : *k < n);
    };
    if (text == *m_unitLastReply) { // `reply` is the one before the packet, or the same text
        if (couldBeOurs(reply)) {
            m_packetGap = false;
            finishFailed(describe() + ": the unit's command index is " + std::to_string(*m_index) +
                             ", and its last reply '" + text +
                             "' may be the packet's or the one before it",
                         LinkFailure::IndexUnexpected,
                         {commandArg(), std::to_string(*m_index), std::to_string(*m_indexBefore),
                          std::to_string(indexAfter())});
            return true;
        }
        // The reply before the packet: its *E never arrived and nothing of it ran.
        m_packetGap = false;
        ++m_resent;
        ++m_stats.resent;
        log(LinkLogKind::Recovery, "packet abandoned, sending again: " + describe());
        m_indexBefore = m_index;
        transmitMain(now);
        return true;
    }
    if (!couldBeOurs(reply))
        return false; // a complaint about '>' itself, or noise: asked again as usual
    m_packetGap = false;
    ++m_recovered;
    ++m_stats.recovered;
    finishOk(reply, text);
    return true;
}

namespace {
std::string whyText(const char *phrase, const std::string &raw, const std::string &extra)
{
    return phrase + (raw.empty() ? std::string() : " '" + raw + "'") + extra;
}
} // namespace

void LinkEngine::recover(const char *phrase, const std::string &raw, const std::string &extra,
                         double now)
{
    const std::string why = whyText(phrase, raw, extra);
    settleThenRetry(describe() + ": " + why, phrase, raw, why, now);
}

void LinkEngine::retryAux(const char *phrase, const std::string &raw, double now)
{
    // Both '@' and '>' are harmless to repeat.
    const std::string why = whyText(phrase, raw, "");
    settleThenRetry(why, phrase, raw, why, now);
}

void LinkEngine::settleThenRetry(const std::string &logText, const char *phrase,
                                 const std::string &raw, const std::string &why, double now)
{
    log(LinkLogKind::Recovery, logText);
    if (++m_attempts > m_options.maxAttempts) {
        finishFailed(describe() + ": " + why + "; gave up after " +
                         std::to_string(m_options.maxAttempts) + " attempts",
                     LinkFailure::GaveUp,
                     {commandArg(), phrase, raw.empty() ? "" : " '" + raw + "'",
                      std::to_string(m_options.maxAttempts)});
        return;
    }
    // A settle pause drops broken bytes. Our own bytes may still be on the wire (a long packet):
    // a query sent now would queue behind them and its reply come late, to be mistaken for
    // another one. Settle after they are out.
    m_state = State::Settle;
    m_deadline = std::max(now, m_txDoneAt) + m_options.settleS;
}

} // namespace frezka::driver
