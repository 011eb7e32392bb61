#pragma once
// Serves a ControllerEmulator on a pseudo-terminal in real time: bytes from the slave side are
// fed to the emulator, its answers are written back paced at the baud rate (10 bits a byte).
// What the PC sends is read at the baud rate too (a byte every 10 bit times), so the pty's
// buffer fills and the PC's port sees the back-pressure of a real line. With a controller baud
// rate set explicitly, a PC port set to another rate (a pty carries the PC's termios setting)
// garbles every byte both ways, as a baud rate mismatch does on a real line.

#include "driver/grinder/controlleremulator.h"

#include <csignal>
#include <deque>
#include <string>

namespace frezka::k51emu {

class PtyServer
{
public:
    // `checkPcBaud`: compare the PC's port setting with `baud` and garble on a mismatch.
    PtyServer(grinder::EmulatorConfig config, int baud, bool fast, bool checkPcBaud = false);
    ~PtyServer();

    // Opens the pty; returns the slave path, or empty with `error` set.
    std::string open(std::string &error);
    // Serves until `stop` becomes non-zero. Returns the process exit code.
    int run(const volatile std::sig_atomic_t &stop, bool verbose, const std::string &storePath);

private:
    bool writePaced(long long elapsedUs);
    // Reads what the wire time allows and feeds it to the emulator; false on a read error.
    // `polled`: poll() asked for input; `readable`: it reported some.
    bool readPaced(long long elapsedUs, bool polled, bool readable, bool verbose);
    // The PC's baud rate from the pty's termios, 0 when unknown.
    int pcBaud() const;
    // True when reading must wait for wire time (nothing is read now).
    bool readThrottled() const;

    grinder::ControllerEmulator m_emulator;
    long long m_byteUs;
    bool m_fast;
    int m_master = -1;
    int m_slave = -1; // kept open so the master never sees a hang-up between clients
    std::deque<std::uint8_t> m_out;
    long long m_creditUs = 0;
    int m_baud;
    bool m_checkPcBaud;
    int m_pcBaud = 0;           // the PC's rate when it differs from m_baud, else 0
    long long m_inCreditUs = 0; // wire time available for bytes from the PC
    bool m_inputBusy = false;   // the last read took all it was allowed: more may be waiting
    long long m_received = 0;   // bytes read from the PC in total
};

} // namespace frezka::k51emu
