#pragma once
// LinkEngine: the request/response layer of the GVE link, with exact recovery.
//
// Pure C++ and clock-free: the owner feeds received bytes and the current time (seconds, any
// monotonic origin), writes out whatever takeOutput() returns, and calls onTime() when
// deadline() has passed. The same engine therefore runs on a real serial port (LinkWorker, with
// a QTimer) and on the emulator's virtual clock (SimRunner), byte for byte alike.
//
// One transaction at a time (the link is strictly half-duplex, docs/gve-protocol.md §2): a single
// command, or a packet of C/B commands (*S .. *E, §2.2). A transaction ends in exactly one
// Outcome. Recovery (§8) when a reply is garbled, fails its checksum or does not come in time:
//
//   settle (let the rest of a broken line arrive, then forget it)
//   a command that is harmless to repeat (queries, settings): send it again; else
//   '@'  -> index of the last command the unit received
//           == the index this transaction leads to   -> it arrived: '>' fetches its reply
//           == the index before this transaction     -> it did not arrive: send it again
//           anything else                            -> Failed (desynchronised; see below)
//   '>'  -> the reply, decoded as the reply to the original command
//
// So a position command is sent again only when the unit provably did not get it. A code 4
// reply while checksums are on may mean the command was damaged on the way (bad checksum: not
// executed, index not advanced, adopted reading §2.1) or a real syntax error: the index tells
// which. Code 2 (watchdog: command incomplete) is resolved the same way. Every step counts as an
// attempt; after LinkOptions::maxAttempts the transaction fails and the link counts as lost.
//
// The engine knows the unit's command index after syncIndex() (or the first recovery that
// learns it): it is advanced for every command except '@' and '>' (adopted reading §8).

#include "driver/link/linkrules.h"
#include "protocol/command.h"
#include "protocol/reply.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace frezka::driver {

inline constexpr double kNoDeadline = std::numeric_limits<double>::infinity();
inline constexpr int kDefaultBaud = 115200;
// The digest's slowest USB-serial adapter, one way (docs/gve-protocol.md §2.2: 1-16 ms): the reply
// allowance never assumes a faster one, whatever the profile says.
inline constexpr double kAdapterLatencyMaxS = 0.016;

struct LinkOptions
{
    // The line's rate, for the transmit-time allowances in timeouts: a packet of 400 vectors
    // takes 0.5 s at 115 200 Bd and 3 s at 19 200 Bd, and a timeout that fires while it is still
    // on the wire sends '@' into it. 0 = not given: MachineCore takes the machine profile's
    // link.baud, the engine alone kDefaultBaud.
    int baud = 0;
    // The serial adapter's latency, one way, seconds (USB converters: 1-16 ms, §2.2); < 0 = not
    // given: MachineCore takes the machine profile's link.latencyMs, the engine alone
    // kAdapterLatencyMaxS.
    double latencyS = -1;
    // The wait for a reply beyond the command's and the reply's transmit times and the round trip
    // through the adapter (twice the larger of latencyS and kAdapterLatencyMaxS): the unit
    // answers at once (§2), so this covers only the PC's own scheduling. Until 2026-11-27 a flat
    // 0.2 s, in which a unit that held a quarter of a second of motion ran dry while the driver
    // waited for a reply that was lost (property seed 81: a brake violation).
    double replyMarginS = 0.05;
    double haltTimeoutS = 60;  // H replies only when the machine has stopped
    double homeTimeoutS = 600; // W replies only when homing has finished
    double settleS = 0.01;     // quiet time after a garbled line before asking '@'
    int maxAttempts = 10;      // recovery steps per transaction before it fails
    // Open packets with *S twice. A lost *S would make the unit run the packet's lines as
    // single commands, where a damaged line leaves a hole that no later check can place; a
    // second *S inside an open packet merely restarts it. The connect sequence tests that the
    // unit accepts it and switches it off otherwise.
    bool doublePacketStart = true;
    // The unit's address on the line (0..6; GVE114 manual §9.5, ordered with the unit): every
    // command for address 0 goes to it instead (address 7, the spindle, stays 7).
    int unitAddress = 0;
    // The line is shared with other units (sharedline.h): a transaction waits, without
    // sending anything, until grantLine() gives it the line; it holds the line until it ends.
    bool sharedLine = false;
    friend bool operator==(const LinkOptions &, const LinkOptions &) = default;
};

enum class OutcomeStatus : std::uint8_t {
    Ok,     // reply received (may carry a unit error code: look at reply.code)
    Failed, // no usable reply after maxAttempts, or the unit's index contradicts ours
};

// Why a transaction failed, for the front ends to word (DriverCode LinkGaveUp, ...); the
// Outcome's English `error` says the same for the log.
enum class LinkFailure : std::uint8_t { None, GaveUp, IndexUnknown, IndexUnexpected };

struct Outcome
{
    OutcomeStatus status = OutcomeStatus::Ok;
    std::vector<protocol::Command> commands; // the command, or the packet's C/B commands
    bool packet = false;
    protocol::Reply reply; // the unit's reply (a packet: the reply to *E)
    int accepted = 0;      // packet: commands the unit accepted (all when reply.code == Ok)
    std::string raw;       // the raw reply line, or the last garbled one
    std::string error;     // Failed: English, names the command and what came back
    LinkFailure failure = LinkFailure::None;
    // GaveUp: the command, what went wrong (a fixed phrase: "no reply", "garbled reply", ...),
    // the last reply quoted after a space (or ""), the attempts; IndexUnknown: the command;
    // IndexUnexpected: the command, the unit's index, the two it could have been. A packet's
    // command is its first with the count of the rest: "'!0C5,0,0' (+41)".
    std::vector<std::string> failureArgs;
    int resent = 0;        // times the transaction was sent again (unit did not get it)
    int recovered = 0;     // times a lost or garbled reply was recovered with '@' / '>'
    std::uint64_t tag = 0; // the caller's tag from start()
};

struct LinkStats
{
    std::int64_t bytesOut = 0;
    std::int64_t bytesIn = 0;
    std::int64_t transactions = 0;
    std::int64_t resent = 0;       // transactions sent again
    std::int64_t recovered = 0;    // replies recovered with '@' and '>'
    std::int64_t garbledLines = 0; // lines that did not decode or did not fit
    std::int64_t noiseLines = 0;   // lines nobody waited for (logged, then dropped)
    std::int64_t timeouts = 0;
    friend bool operator==(const LinkStats &, const LinkStats &) = default;
};

enum class LinkLogKind : std::uint8_t { Sent, Received, Noise, Recovery, Error };

class LinkEngine
{
public:
    explicit LinkEngine(LinkOptions options = {});

    // ---- transactions (only when idle())
    bool idle() const { return m_state == State::Idle; }
    // Sends one command. The Outcome arrives through onOutcome.
    void start(const protocol::Command &command, double now, std::uint64_t tag = 0);
    // Sends C/B commands as one packet.
    void startPacket(std::vector<protocol::Command> commands, double now, std::uint64_t tag = 0);
    // Asks '@' and takes the answer as the unit's current index (after connecting, after a
    // desynchronisation). Outcome: the '@' reply.
    void syncIndex(double now, std::uint64_t tag = 0);

    // ---- a shared line (LinkOptions::sharedLine)
    // A transaction waits for the line (nothing sent yet).
    bool wantsLine() const { return m_state == State::AwaitGrant; }
    // Starts the waiting transaction: its bytes go out now.
    void grantLine(double now);
    // The commands of the transaction in flight (or waiting), for the shared line's log.
    std::size_t commandsInFlight() const { return m_commands.size(); }

    // ---- I/O
    void receive(std::string_view bytes, double now);
    void onTime(double now);
    // Absolute time of the next timeout, kNoDeadline when none.
    double deadline() const { return m_deadline; }
    // Bytes to write now (the caller must write all of them, in order).
    std::string takeOutput();
    bool hasOutput() const { return !m_out.empty(); }

    // ---- state
    bool checksums() const { return m_checksums; }
    // Sets the framing after the unit's checksum state is known (the engine also follows
    // successful %+ / %- by itself).
    void setChecksums(bool on) { m_checksums = on; }
    void setDoublePacketStart(bool on) { m_options.doublePacketStart = on; }
    // The line's rate (a machine profile changed while connected); 0 = kDefaultBaud.
    void setBaud(int baud) { m_options.baud = baud > 0 ? baud : kDefaultBaud; }
    std::optional<int> unitIndex() const { return m_index; }
    const LinkStats &stats() const { return m_stats; }
    const LinkOptions &options() const { return m_options; }
    // Forgets the transaction in flight and all pending bytes (after the port closed). The
    // transaction gets no Outcome; the caller knows it was lost.
    void reset();
    // Seconds a message of n bytes takes on the wire.
    double wireTime(std::size_t bytes) const;
    // Seconds a reply may take beyond the transmit times before it counts as lost: the round
    // trip through the adapter and LinkOptions::replyMarginS.
    double replyAllowanceS() const;

    std::function<void(const Outcome &)> onOutcome;
    std::function<void(LinkLogKind, const std::string &)> onLog;

private:
    enum class State : std::uint8_t {
        Idle,
        AwaitGrant,
        AwaitReply,
        Settle,
        AwaitIndex,
        AwaitRepeat
    };

    void beginTransaction(double now);
    // The transaction starts now, or waits for the shared line (grantLine).
    void beginOrWait(double now);
    // The command as it goes to this unit: address 0 becomes LinkOptions::unitAddress.
    protocol::Command routed(protocol::Command c) const;
    void transmitMain(double now);
    void sendAux(const protocol::Command &c, State next, double now,
                 LinkLogKind kind = LinkLogKind::Recovery);
    void handleLine(const protocol::Line &line, double now);
    // A plain code-2 reply: the unit's watchdog answering a command cut short (m_watchdogDue).
    bool lateWatchdog(const protocol::Line &line) const;
    void onMainReply(const protocol::Line &line, double now);
    void onIndexReply(const protocol::Line &line, double now);
    void onRepeatReply(const protocol::Line &line, double now);
    // Decodes a reply to `c`; nullopt (and raw/err set) when garbled or not fitting.
    std::optional<protocol::Reply> decodeFor(const protocol::Command &c, const std::string &line,
                                             std::string &err);
    // phrase: what went wrong, a fixed phrase (linkFailurePhrases); raw: the reply as it came
    // ("" for none); extra: English detail for the log only.
    void recover(const char *phrase, const std::string &raw, const std::string &extra, double now);
    void retryAux(const char *phrase, const std::string &raw, double now);
    // Counts an attempt (failing past maxAttempts), then settles before the next one.
    void settleThenRetry(const std::string &logText, const char *phrase, const std::string &raw,
                         const std::string &why, double now);
    void finishOk(const protocol::Reply &r, const std::string &raw);
    void finishFailed(const std::string &why, LinkFailure failure,
                      std::vector<std::string> failureArgs);
    void finish();
    void log(LinkLogKind kind, const std::string &text);
    int indexAfter() const; // the unit's index once this transaction has arrived
    bool exact() const;     // the transaction must arrive exactly once (see mustArriveOnce)
    double timeoutFor(const protocol::Command &c, std::size_t bytes, double now);
    const protocol::Command &mainCommand() const;
    std::string describe() const;
    std::string commandArg() const; // language-neutral: "'!0F'", "'!0C5,0,0' (+41)"

    LinkOptions m_options;
    State m_state = State::Idle;
    bool m_checksums = false;
    std::optional<int> m_index; // the unit's index of the last command received
    bool m_syncing = false;     // the transaction is syncIndex()
    bool m_presync = false;     // asking '@' before the transaction (index unknown)
    protocol::ReplyDecoder m_decoder;
    std::string m_out;
    double m_deadline = kNoDeadline;
    // the transaction in flight
    std::vector<protocol::Command> m_commands;
    bool m_packet = false;
    std::uint64_t m_tag = 0;
    std::string m_wire; // its bytes, as sent
    int m_attempts = 0;
    double m_txDoneAt = 0;       // when the bytes written so far have left on the wire
    std::string m_lastRepeat;    // a doubtful answer to '>' (see onRepeatReply)
    bool m_doubtfulSeen = false; // a packet got a plain 4 / 2: its counted reply may follow
    int m_resent = 0;
    int m_recovered = 0;
    std::string m_lastRaw;
    std::optional<int> m_indexBefore;
    // The reply the unit would repeat on '>' now: that of the last command that advanced its
    // index, as received; unknown after a failed or doubtful transaction and after J.
    std::optional<std::string> m_unitLastReply;
    // '>' asked after a packet only part of whose lines counted (see onIndexReply).
    bool m_packetGap = false;
    // The reply to this transaction's command timed out: the unit may still answer it with its
    // watchdog's code 2 (the command was cut short), later than the reply allowance. The first
    // such line is dropped, whatever we wait for then (see handleLine).
    bool m_watchdogDue = false;
    // The packet's lines were answered one by one: both its *S lines arrived damaged, so the
    // unit ran each C and B as a command of its own, queueing some and refusing others for a full
    // queue (a gap in the path when it ran meanwhile). Its fate is unknown whatever comes back:
    // the engine drops the rest of those answers until the packet's deadline, then fails it
    // (see onMainReply).
    bool m_ranSingly = false;
    // A reply without a count that only a single command gives (not a complaint, 4 or 2).
    bool answeredSingly(const protocol::Line &line) const;
    bool packetGapAnswer(const protocol::Reply &reply, const std::string &text, double now);
    LinkStats m_stats;
};

} // namespace frezka::driver
