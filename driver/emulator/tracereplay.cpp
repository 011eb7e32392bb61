#include "tracereplay.h"

#include <cmath>
#include <limits>

namespace frezka::emulator {
namespace {

std::int64_t nsOfMs(double ms)
{
    return std::llround(ms * 1e6);
}

} // namespace

TraceReplay::TraceReplay(SerialTrace trace, bool freePolls)
    : m_trace(std::move(trace))
    , m_freePolls(freePolls)
{
    scheduleReplies(0); // what the unit said before the first command (a banner, a stray byte)
}

void TraceReplay::skipEvents()
{
    while (m_next < m_trace.entries.size() &&
           m_trace.entries[m_next].direction == TraceDirection::Event)
        ++m_next;
}

// Schedules the unit lines that follow m_next, relative to the command recorded at anchorMs.
void TraceReplay::scheduleReplies(double anchorMs)
{
    for (skipEvents(); m_next < m_trace.entries.size(); skipEvents()) {
        const TraceEntry &e = m_trace.entries[m_next];
        if (e.direction != TraceDirection::ToPc)
            break;
        const std::int64_t after = std::max<std::int64_t>(0, nsOfMs(e.timeMs) - nsOfMs(anchorMs));
        m_due.push_back({m_nowNs + after, m_next});
        ++m_next;
    }
}

void TraceReplay::diverge(const char *text, int line, std::vector<std::string> args)
{
    if (!m_divergence)
        m_divergence = TraceMessage{text, std::move(args), line};
}

void TraceReplay::pcWrite(std::string_view bytes)
{
    for (const char c : bytes) {
        m_partial += c;
        if (c == '\r') {
            onLine(m_partial);
            m_partial.clear();
        }
    }
}

void TraceReplay::onLine(const std::string &line)
{
    if (m_divergence)
        return;
    skipEvents();
    if (!m_due.empty()) {
        const TraceEntry &reply = m_trace.entries[m_due.front().entry];
        diverge(QT_TRANSLATE_NOOP("SerialTrace",
                                  "trace line %1: the driver sent '%2' before the unit's line "
                                  "'%3' that the trace has first"),
                reply.fileLine,
                {std::to_string(reply.fileLine), escapeTraceBytes(line),
                 escapeTraceBytes(reply.bytes)});
        return;
    }
    if (!m_freePolls && m_next >= m_trace.entries.size()) {
        ++m_afterEnd;
        return;
    }
    if (m_freePolls) {
        skipPollsExpected(line);
        if (m_next >= m_trace.entries.size() || m_trace.entries[m_next].bytes != line) {
            if (isRoutinePoll(line) && answerPoll(line))
                return;
        }
        if (m_next >= m_trace.entries.size()) {
            ++m_afterEnd;
            return;
        }
    }
    const TraceEntry &expected = m_trace.entries[m_next];
    if (expected.bytes != line) {
        diverge(QT_TRANSLATE_NOOP("SerialTrace",
                                  "trace line %1: expected '%2', got '%3' (the last unit line "
                                  "given was trace line %4)"),
                expected.fileLine,
                {std::to_string(expected.fileLine), escapeTraceBytes(expected.bytes),
                 escapeTraceBytes(line), std::to_string(m_lastReplyLine)});
        return;
    }
    ++m_next;
    scheduleReplies(expected.timeMs);
}

bool TraceReplay::isRoutinePoll(std::string_view line)
{
    if (line.size() < 4 || line.substr(0, 2) != "!0")
        return false;
    const std::string_view body = line.substr(2, line.find_first_of(",\r") - 2);
    return body == "P" || body == "PF" || body == "P4" || body == "F" || body == "I1" ||
           body == "I2";
}

// The index after entry `i`'s unit lines (and events).
std::size_t TraceReplay::afterReplies(std::size_t i) const
{
    for (++i; i < m_trace.entries.size() && m_trace.entries[i].direction != TraceDirection::ToUnit;)
        ++i;
    return i;
}

// Free polls: a poll the record has next but the driver did not send (now) is passed over,
// with its replies, while the driver's line is not that poll.
void TraceReplay::skipPollsExpected(const std::string &line)
{
    for (skipEvents(); m_next < m_trace.entries.size(); skipEvents()) {
        const TraceEntry &e = m_trace.entries[m_next];
        if (e.direction != TraceDirection::ToUnit || e.bytes == line || !isRoutinePoll(e.bytes))
            return;
        m_next = afterReplies(m_next);
    }
}

// Free polls: a poll the record does not have here is answered as the unit answered the same
// poll last before this point of the record (or first after it), with that reply's delay.
bool TraceReplay::answerPoll(const std::string &line)
{
    std::size_t found = m_trace.entries.size();
    for (std::size_t i = std::min(m_next, m_trace.entries.size()); i-- > 0;) {
        if (m_trace.entries[i].direction == TraceDirection::ToUnit &&
            m_trace.entries[i].bytes == line) {
            found = i;
            break;
        }
    }
    for (std::size_t i = m_next; found == m_trace.entries.size() && i < m_trace.entries.size();
         ++i) {
        if (m_trace.entries[i].direction == TraceDirection::ToUnit &&
            m_trace.entries[i].bytes == line)
            found = i;
    }
    if (found == m_trace.entries.size())
        return false;
    const std::int64_t anchor = nsOfMs(m_trace.entries[found].timeMs);
    const std::size_t end = afterReplies(found);
    for (std::size_t i = found + 1; i < end; ++i) {
        const TraceEntry &e = m_trace.entries[i];
        if (e.direction == TraceDirection::ToPc)
            m_due.push_back({m_nowNs + std::max<std::int64_t>(0, nsOfMs(e.timeMs) - anchor), i});
    }
    ++m_pollsAnsweredFree;
    return true;
}

std::string TraceReplay::pcRead()
{
    std::string out;
    while (!m_divergence && !m_due.empty() && m_due.front().atNs <= m_nowNs) {
        const TraceEntry &e = m_trace.entries[m_due.front().entry];
        out += e.bytes;
        m_lastReplyLine = e.fileLine;
        m_due.pop_front();
    }
    return out;
}

double TraceReplay::nextEventIn() const
{
    if (m_divergence || m_due.empty())
        return std::numeric_limits<double>::infinity();
    return static_cast<double>(std::max<std::int64_t>(0, m_due.front().atNs - m_nowNs)) * 1e-9;
}

void TraceReplay::advance(double seconds)
{
    m_nowNs += std::max<std::int64_t>(0, std::llround(seconds * 1e9));
}

bool TraceReplay::finished() const
{
    std::size_t i = m_next;
    while (i < m_trace.entries.size()) {
        const TraceEntry &e = m_trace.entries[i];
        if (e.direction == TraceDirection::Event)
            ++i;
        else if (m_freePolls && e.direction == TraceDirection::ToUnit && isRoutinePoll(e.bytes))
            i = afterReplies(i); // polls the driver need not send at the end
        else
            break;
    }
    return !m_divergence && m_due.empty() && i >= m_trace.entries.size();
}

} // namespace frezka::emulator
