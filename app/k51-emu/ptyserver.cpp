#include "app/k51-emu/ptyserver.h"

#include "driver/grinder/wiremodel.h"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

namespace frezka::k51emu {

using namespace frezka::grinder;

PtyServer::PtyServer(EmulatorConfig config, int baud, bool fast, bool checkPcBaud)
    : m_emulator(std::move(config))
    , m_byteUs(10'000'000LL / (baud > 0 ? baud : 9600))
    , m_fast(fast)
    , m_baud(baud > 0 ? baud : 9600)
    , m_checkPcBaud(checkPcBaud)
{}

int PtyServer::pcBaud() const
{
    termios tio{};
    if (m_slave < 0 || ::tcgetattr(m_slave, &tio) != 0)
        return 0;
    static const std::pair<speed_t, int> kSpeeds[] = {
        {B1200, 1200},   {B2400, 2400},   {B4800, 4800},     {B9600, 9600},    {B19200, 19200},
        {B38400, 38400}, {B57600, 57600}, {B115200, 115200}, {B230400, 230400}};
    const speed_t speed = ::cfgetospeed(&tio);
    for (const auto &[code, baud] : kSpeeds) {
        if (code == speed)
            return baud;
    }
    return 0;
}

bool PtyServer::readThrottled() const
{
    return !m_fast && m_inputBusy && m_inCreditUs < m_byteUs;
}

// The wire delivers one byte per byte time; an idle line has at most two byte times in hand.
bool PtyServer::readPaced(long long elapsedUs, bool polled, bool readable, bool verbose)
{
    const long long lineByteUs = m_pcBaud > 0 ? 10'000'000LL / m_pcBaud : m_byteUs;
    m_inCreditUs =
        m_inputBusy ? m_inCreditUs + elapsedUs : std::min(m_inCreditUs + elapsedUs, 2 * lineByteUs);
    const std::size_t allowed =
        m_fast ? 4096 : std::min<std::size_t>(4096, std::size_t(m_inCreditUs / lineByteUs));
    if (!readable) {
        if (polled)
            m_inputBusy = false; // the line is idle
        return true;
    }
    if (allowed == 0)
        return true;
    std::uint8_t buffer[4096];
    const ssize_t n = ::read(m_master, buffer, allowed);
    if (n < 0) {
        m_inputBusy = false;
        return errno == EAGAIN || errno == EINTR || errno == EIO;
    }
    m_inputBusy = std::size_t(n) == allowed;
    if (!m_fast)
        m_inCreditUs -= n * lineByteUs;
    const long long before = m_received;
    m_received += n;
    if (verbose && m_received / 1024 != before / 1024)
        std::fprintf(stderr, "k51-emu: received %lld bytes\n", m_received);
    if (m_pcBaud > 0)
        m_emulator.feed(resampleUart(Bytes(buffer, buffer + n), m_pcBaud, m_baud));
    else
        m_emulator.feed(buffer, std::size_t(n));
    return true;
}

PtyServer::~PtyServer()
{
    if (m_slave >= 0)
        ::close(m_slave);
    if (m_master >= 0)
        ::close(m_master);
}

std::string PtyServer::open(std::string &error)
{
    m_master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (m_master < 0 || ::grantpt(m_master) != 0 || ::unlockpt(m_master) != 0) {
        error = std::string("cannot open a pseudo-terminal: ") + std::strerror(errno);
        return {};
    }
    const char *name = ::ptsname(m_master);
    if (!name) {
        error = std::string("ptsname failed: ") + std::strerror(errno);
        return {};
    }
    const std::string path = name;
    m_slave = ::open(path.c_str(), O_RDWR | O_NOCTTY);
    if (m_slave < 0) {
        error = "cannot open " + path + ": " + std::strerror(errno);
        return {};
    }
    termios tio{};
    if (::tcgetattr(m_slave, &tio) == 0) {
        ::cfmakeraw(&tio);
        ::tcsetattr(m_slave, TCSANOW, &tio);
    }
    ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
    return path;
}

// Writes what the wire time since the last call allows (everything with --fast).
bool PtyServer::writePaced(long long elapsedUs)
{
    if (m_out.empty()) {
        m_creditUs = 0;
        return true;
    }
    m_creditUs += elapsedUs;
    std::size_t allowed = m_fast ? m_out.size() : std::size_t(m_creditUs / m_byteUs);
    if (allowed == 0)
        return true;
    allowed = std::min(allowed, m_out.size());
    std::string chunk(m_out.begin(), m_out.begin() + static_cast<std::ptrdiff_t>(allowed));
    const ssize_t n = ::write(m_master, chunk.data(), chunk.size());
    if (n < 0)
        return errno == EAGAIN || errno == EINTR;
    m_out.erase(m_out.begin(), m_out.begin() + n);
    if (!m_fast)
        m_creditUs -= n * m_byteUs;
    return true;
}

int PtyServer::run(const volatile std::sig_atomic_t &stop, bool verbose,
                   const std::string &storePath)
{
    using Clock = std::chrono::steady_clock;
    auto last = Clock::now();
    int stored = 0;
    int tables = 0;
    while (!stop) {
        if (m_checkPcBaud) {
            const int pc = pcBaud();
            const int mismatch = pc > 0 && pc != m_baud ? pc : 0;
            if (mismatch != m_pcBaud && mismatch > 0)
                std::fprintf(stderr,
                             "k51-emu: the PC's port is set to %d Bd, the controller to %d Bd: "
                             "every byte arrives garbled\n",
                             mismatch, m_baud);
            m_pcBaud = mismatch;
        }
        const bool throttled = readThrottled();
        const int timeoutMs = m_out.empty() && !m_inputBusy ? 10 : 1;
        pollfd pfd{m_master, short(throttled ? 0 : POLLIN), 0};
        const int ready = ::poll(&pfd, 1, timeoutMs);
        if (ready < 0 && errno != EINTR) {
            std::fprintf(stderr, "k51-emu: poll: %s\n", std::strerror(errno));
            return 1;
        }
        const auto now = Clock::now();
        const long long elapsedUs =
            std::chrono::duration_cast<std::chrono::microseconds>(now - last).count();
        last = now;
        m_emulator.advance(elapsedUs);
        if (!readPaced(elapsedUs, !throttled, ready > 0 && (pfd.revents & POLLIN), verbose)) {
            std::fprintf(stderr, "k51-emu: read: %s\n", std::strerror(errno));
            return 1;
        }
        const Bytes out = m_pcBaud > 0 ? resampleUart(m_emulator.takeOutput(), m_baud, m_pcBaud)
                                       : m_emulator.takeOutput();
        m_out.insert(m_out.end(), out.begin(), out.end());
        if (!writePaced(elapsedUs)) {
            std::fprintf(stderr, "k51-emu: write: %s\n", std::strerror(errno));
            return 1;
        }
        for (const std::string &line : m_emulator.takeLog()) {
            if (verbose)
                std::fprintf(stderr, "k51-emu: %s\n", line.c_str());
        }
        if (m_emulator.tablesStored() != tables) {
            tables = m_emulator.tablesStored();
            std::fprintf(stderr, "k51-emu: stored a table of %zu bytes\n",
                         m_emulator.table().size());
        }
        if (m_emulator.loadsStored() != stored) {
            stored = m_emulator.loadsStored();
            std::fprintf(stderr, "k51-emu: stored %zu bytes, header \"%s\"\n",
                         m_emulator.image().size(), headerText(m_emulator.header()).c_str());
            if (!storePath.empty()) {
                std::ofstream file(storePath, std::ios::binary | std::ios::trunc);
                file.write(reinterpret_cast<const char *>(m_emulator.image().data()),
                           std::streamsize(m_emulator.image().size()));
                if (!file)
                    std::fprintf(stderr, "k51-emu: cannot write %s\n", storePath.c_str());
            }
        }
    }
    return 0;
}

} // namespace frezka::k51emu
