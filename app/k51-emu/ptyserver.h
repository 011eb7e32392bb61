#pragma once
// Serves a ControllerEmulator on a pseudo-terminal in real time: bytes from the slave side are
// fed to the emulator, its answers are written back paced at the baud rate (10 bits a byte).

#include "driver/grinder/controlleremulator.h"

#include <csignal>
#include <deque>
#include <string>

namespace frezka::k51emu {

class PtyServer
{
public:
    PtyServer(grinder::EmulatorConfig config, int baud, bool fast);
    ~PtyServer();

    // Opens the pty; returns the slave path, or empty with `error` set.
    std::string open(std::string &error);
    // Serves until `stop` becomes non-zero. Returns the process exit code.
    int run(const volatile std::sig_atomic_t &stop, bool verbose, const std::string &storePath);

private:
    bool writePaced(long long elapsedUs);

    grinder::ControllerEmulator m_emulator;
    long long m_byteUs;
    bool m_fast;
    int m_master = -1;
    int m_slave = -1; // kept open so the master never sees a hang-up between clients
    std::deque<std::uint8_t> m_out;
    long long m_creditUs = 0;
};

} // namespace frezka::k51emu
