#pragma once
// Serves a Simulation (unit + wire model) on a pseudo-terminal, with the simulation clock
// following the wall clock: bytes the client writes enter the wire when they are read, and the
// unit's replies are written to the terminal when the wire model delivers them. With a replay
// (--replay), a recorded unit (emulator::TraceReplay) takes the simulation's place; a divergence
// from the record is reported and ends the event loop with exit code 3.

#include "emuoptions.h"

#include "driver/emulator/tracereplay.h"

#include <QElapsedTimer>
#include <QObject>
#include <QSocketNotifier>
#include <QTimer>

#include <memory>
#include <string>

namespace frezka::gveemu {

class PtyServer : public QObject
{
    Q_OBJECT

public:
    explicit PtyServer(const EmuOptions &options, QObject *parent = nullptr);
    // Plays `trace` instead of the emulated unit.
    void setReplay(emulator::SerialTrace trace);
    ~PtyServer() override;

    // Creates the terminal (raw mode). Returns false with a message on failure.
    bool open(QString &error);
    QString slavePath() const { return m_slavePath; }
    // Turns the simulated MPG wheel now (--wheel); false when the unit ignores it (MPG off,
    // not enabled in its EEPROM, an interrupt pending).
    bool turnWheel(const WheelTurn &turn);

private:
    void onReadable();
    void onWritable();
    void pump();
    void flushOut();
    void log(const char *direction, const std::string &bytes) const;
    // The far end: the simulation, or the replay when there is one.
    double farNow() const;
    void farAdvance(double seconds);
    void farWrite(const std::string &bytes);
    std::string farRead();
    double farNextEventIn() const;
    void checkReplay();

    emulator::Simulation m_sim;
    std::unique_ptr<emulator::TraceReplay> m_replay;
    bool m_replayEndTold = false;
    bool m_verbose;
    int m_master = -1;
    int m_slave = -1; // kept open so the master never sees a hang-up between clients
    QString m_slavePath;
    std::unique_ptr<QSocketNotifier> m_readNotifier;
    std::unique_ptr<QSocketNotifier> m_writeNotifier;
    QTimer m_timer;
    QElapsedTimer m_clock;
    std::string m_out; // bytes delivered by the wire model, not yet written to the terminal
};

} // namespace frezka::gveemu
