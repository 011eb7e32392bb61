#pragma once
// TraceReplay: the unit's side of a recorded serial trace, played back against a driver.
//
// The PC's bytes are cut into lines (up to CR) and each is compared with the next command of the
// trace; when it matches, the unit lines recorded after that command are given back, each as
// long after the match as it came after the command in the record (so the record's timing, wire
// time and latency included, is kept). A line that differs, or one sent while a recorded reply
// is still due, is a divergence: the replay names the trace line, what it expected and what it
// got, and answers nothing more. Commands sent after the last line of the trace are counted but
// not an error (a record ends where it was saved). Event entries are not on the wire: skipped.
//
// With free polls, the driver's routine polls (P, PF, P4, F, I1, I2 on address 0) need not come
// where the record has them: a record made in real time has them where the wall clock put them,
// and a driver replaying it on another clock asks at other moments. A poll the record has next
// is passed over (with its replies) when the driver sends something else, and a poll the record
// does not have there is answered as the unit answered that poll last (first, if the record has
// not had it yet). Every other command must still come in the record's order.
// A virtual clock in whole nanoseconds (as the trace's times): a trace recorded on such a clock
// (driver::TracingPort) gives the driver the very same instants again, so that where two of its
// timers met at one instant in the record they meet again. Pure and deterministic.

#include "driver/emulator/serialtrace.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>

namespace frezka::emulator {

class TraceReplay
{
public:
    explicit TraceReplay(SerialTrace trace, bool freePolls = false);
    // A routine poll of the driver: "!0P", "!0PF", "!0P4", "!0F", "!0I1", "!0I2" (checksum
    // and CR allowed).
    static bool isRoutinePoll(std::string_view line);

    // Bytes from the PC at now().
    void pcWrite(std::string_view bytes);
    // The unit's lines due by now().
    std::string pcRead();
    double now() const { return static_cast<double>(m_nowNs) * 1e-9; }
    // Seconds until the next recorded line is due; infinity when none is.
    double nextEventIn() const;
    // Moves the clock on by `seconds`, rounded to the nanosecond.
    void advance(double seconds);

    // The first divergence (empty while the driver does what the trace recorded).
    const TraceMessage &divergence() const { return m_divergence; }
    // Every wire line of the trace was matched or given.
    bool finished() const;
    // The file line of the last unit line given (0 = none yet): where to look when the driver
    // went another way after it.
    int lastReplyLine() const { return m_lastReplyLine; }
    // Whole lines the PC sent after the end of the trace.
    int commandsAfterEnd() const { return m_afterEnd; }
    // Free polls: polls answered from elsewhere in the record.
    int pollsAnsweredFree() const { return m_pollsAnsweredFree; }
    const SerialTrace &trace() const { return m_trace; }

private:
    struct Due
    {
        std::int64_t atNs = 0;
        std::size_t entry = 0;
    };
    void onLine(const std::string &line);
    void scheduleReplies(double anchorMs);
    void skipEvents();
    std::size_t afterReplies(std::size_t i) const;
    void skipPollsExpected(const std::string &line);
    bool answerPoll(const std::string &line);
    void diverge(const char *text, int line, std::vector<std::string> args);

    SerialTrace m_trace;
    std::size_t m_next = 0; // the next entry to match or schedule
    std::deque<Due> m_due;
    std::string m_partial; // PC bytes of a line not yet ended by CR
    std::int64_t m_nowNs = 0;
    TraceMessage m_divergence;
    int m_lastReplyLine = 0;
    int m_afterEnd = 0;
    bool m_freePolls = false;
    int m_pollsAnsweredFree = 0;
};

} // namespace frezka::emulator
