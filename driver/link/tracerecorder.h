#pragma once
// TraceRecorder: the serial line of a session, both ways, kept in a bounded ring (the last N
// bytes of trace text) in the format of docs/serial-trace.md, saved on demand or on an alarm.
//
// The transports made by createTransport record into the process's one recorder, session(): a
// process has one link, and the front ends (the GUI's menu and console, frezka-cli --trace)
// save it from their own thread. Its one mutex guards the ring and the header: the link thread
// records, any thread saves.

#include "driver/emulator/serialtrace.h"
#include "driver/link/machinestate.h"

#include <QString>

#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace frezka::driver {

// The event entries the driver's observers write and the regression helper compares: "mode
// Homing", "error 209: <the English message>", "job finished ok".
std::string traceModeEvent(MachineMode mode);
std::string traceErrorEvent(const MachineError &error);
std::string traceJobEvent(bool ok);
// Whether an error is an alarm whose trace is saved by itself (the unit or the link failed, a
// job stopped: codes 2xx and 3xx).
bool isTraceAlarm(const MachineError &error);

class TraceRecorder
{
public:
    static constexpr std::int64_t kDefaultLimitBytes = 4 * 1024 * 1024;

    // The record of this process's link.
    static TraceRecorder &session();

    // The ring's size in bytes of trace text; 0 switches recording off (and drops the record).
    void setLimitBytes(std::int64_t bytes);
    std::int64_t limitBytes() const;
    bool enabled() const { return limitBytes() > 0; }
    // "Frezka 0.9.0" for the header of every record from now on.
    void setProgramVersion(const std::string &version);

    // Starts a new record at nowS (seconds on the caller's clock): the old one is dropped, the
    // header holds the program's version and `header` (variant, baud, port ...).
    void begin(std::vector<std::pair<std::string, std::string>> header, double nowS);
    // Adds or replaces a header value of the current record ("operation", "program" ...).
    void setValue(const std::string &key, const std::string &value);
    // Bytes on the line at nowS; cut into entries at each CR.
    void record(emulator::TraceDirection direction, std::string_view bytes, double nowS);
    // What the driver showed at nowS (its mode, an error): an event entry.
    void note(const std::string &event, double nowS);

    // The record so far, a line not yet ended by CR included.
    emulator::SerialTrace snapshot() const;
    // Writes snapshot() to `path` (folders created). False with the reason, translated.
    bool save(const QString &path, QString *error) const;
    // Saves into alarmFolder() as trace-YYYYMMDD-hhmmss-zzz.txt; the path, or empty when
    // recording is off, no folder is set, or the file cannot be written (the reason in *error).
    QString saveAlarm(QString *error) const;
    // Where saveAlarm writes; empty (the default) = nowhere. The front ends set
    // defaultAlarmFolder(); tests and other users of the driver leave the user's folders alone.
    void setAlarmFolder(const QString &folder);
    QString alarmFolder() const;
    // $XDG_STATE_HOME/frezka/traces (~/.local/state/frezka/traces).
    static QString defaultAlarmFolder();

private:
    struct Open
    {
        std::string bytes;
        double timeMs = 0;
    };
    void push(emulator::TraceEntry entry);
    void dropOverLimit();
    double msOf(double nowS) const { return (nowS - m_startS) * 1000.0; }

    mutable std::mutex m_mutex; // guards every field below
    std::int64_t m_limit = kDefaultLimitBytes;
    std::string m_version;
    emulator::SerialTrace m_trace; // header; entries unused (the ring holds them)
    std::deque<emulator::TraceEntry> m_ring;
    std::int64_t m_ringBytes = 0;
    std::int64_t m_dropped = 0;
    Open m_open[2]; // the line being received per direction: [0] to the unit, [1] to the PC
    double m_startS = 0;
    QString m_alarmFolder;
};

} // namespace frezka::driver
