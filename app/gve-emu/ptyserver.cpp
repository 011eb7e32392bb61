#include "ptyserver.h"

#include <QCoreApplication>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

namespace frezka::gveemu {

PtyServer::PtyServer(const EmuOptions &options, QObject *parent)
    : QObject(parent)
    , m_sim(options.simulation)
    , m_verbose(options.verbose)
{
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &PtyServer::pump);
}

PtyServer::~PtyServer()
{
    if (m_slave >= 0)
        ::close(m_slave);
    if (m_master >= 0)
        ::close(m_master);
}

bool PtyServer::open(QString &error)
{
    auto fail = [&error](const char *what) {
        error = QCoreApplication::translate("gve-emu", "cannot create the pseudo-terminal "
                                                       "(%1): %2")
                    .arg(QLatin1String(what), QString::fromLocal8Bit(std::strerror(errno)));
        return false;
    };
    m_master = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (m_master < 0)
        return fail("posix_openpt");
    if (::grantpt(m_master) != 0 || ::unlockpt(m_master) != 0)
        return fail("grantpt/unlockpt");
    const char *name = ::ptsname(m_master);
    if (!name)
        return fail("ptsname");
    m_slavePath = QString::fromLocal8Bit(name);
    m_slave = ::open(name, O_RDWR | O_NOCTTY);
    if (m_slave < 0)
        return fail("open slave");
    termios tio{};
    if (::tcgetattr(m_slave, &tio) != 0)
        return fail("tcgetattr");
    ::cfmakeraw(&tio);
    if (::tcsetattr(m_slave, TCSANOW, &tio) != 0)
        return fail("tcsetattr");
    m_readNotifier = std::make_unique<QSocketNotifier>(m_master, QSocketNotifier::Read);
    connect(m_readNotifier.get(), &QSocketNotifier::activated, this, &PtyServer::onReadable);
    m_writeNotifier = std::make_unique<QSocketNotifier>(m_master, QSocketNotifier::Write);
    m_writeNotifier->setEnabled(false);
    connect(m_writeNotifier.get(), &QSocketNotifier::activated, this, &PtyServer::onWritable);
    m_clock.start();
    return true;
}

void PtyServer::onReadable()
{
    pump(); // bring the simulation to now before the new bytes enter the wire
    char buf[4096];
    for (;;) {
        const ssize_t n = ::read(m_master, buf, sizeof buf);
        if (n > 0) {
            const std::string bytes(buf, static_cast<std::size_t>(n));
            log("pc>", bytes);
            farWrite(bytes);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        break; // EAGAIN: all read; EIO cannot happen while m_slave is open
    }
    pump();
}

bool PtyServer::turnWheel(const WheelTurn &turn)
{
    if (m_replay)
        return false;
    pump(); // the unit at the wall clock's time first
    emulator::Unit &unit = m_sim.unit();
    unit.setWheelAxis(turn.axisPosition);
    unit.setWheelMultiplier(turn.multiplier);
    const bool moved = unit.turnWheel(turn.detents);
    pump();
    return moved;
}

void PtyServer::pump()
{
    const double wall = static_cast<double>(m_clock.nsecsElapsed()) / 1e9;
    if (wall > farNow())
        farAdvance(wall - farNow());
    if (std::string out = farRead(); !out.empty()) {
        log("<unit", out);
        m_out += out;
        flushOut();
    }
    // Wake up at the next event (a byte, a reply, a vector end...). A far event is re-checked
    // hourly: that keeps the interval inside an int and costs nothing.
    checkReplay();
    const double next = farNextEventIn();
    constexpr double kLongestWaitMs = 3600.0 * 1000.0;
    if (std::isfinite(next))
        m_timer.start(static_cast<int>(std::ceil(std::min(next * 1000.0, kLongestWaitMs))));
    else
        m_timer.stop();
}

void PtyServer::flushOut()
{
    while (!m_out.empty()) {
        const ssize_t n = ::write(m_master, m_out.data(), m_out.size());
        if (n > 0) {
            m_out.erase(0, static_cast<std::size_t>(n));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        break; // EAGAIN: the client does not read; try again when writable
    }
    m_writeNotifier->setEnabled(!m_out.empty());
}

void PtyServer::onWritable()
{
    flushOut();
}

void PtyServer::log(const char *direction, const std::string &bytes) const
{
    if (!m_verbose)
        return;
    std::string shown;
    for (char c : bytes) {
        if (c == '\r')
            shown += "\\r";
        else if (c == '\n')
            shown += "\\n";
        else if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned char>(c));
            shown += hex;
        } else {
            shown += c;
        }
    }
    std::fprintf(stderr, "%10.6f %s %s\n", farNow(), direction, shown.c_str());
}

void PtyServer::setReplay(emulator::SerialTrace trace)
{
    // The driver's polls come when its wall clock says: free (emulator::TraceReplay).
    m_replay = std::make_unique<emulator::TraceReplay>(std::move(trace), true);
}

double PtyServer::farNow() const
{
    return m_replay ? m_replay->now() : m_sim.now();
}

void PtyServer::farAdvance(double seconds)
{
    if (m_replay)
        m_replay->advance(seconds);
    else
        m_sim.advance(seconds);
}

void PtyServer::farWrite(const std::string &bytes)
{
    if (m_replay)
        m_replay->pcWrite(bytes);
    else
        m_sim.pcWrite(bytes);
}

std::string PtyServer::farRead()
{
    return m_replay ? m_replay->pcRead() : m_sim.pcRead();
}

double PtyServer::farNextEventIn() const
{
    return m_replay ? m_replay->nextEventIn() : m_sim.nextEventIn();
}

// A replay that diverged ends gve-emu (exit 3) with the trace line; its end is told once.
void PtyServer::checkReplay()
{
    if (!m_replay)
        return;
    if (const emulator::TraceMessage &d = m_replay->divergence()) {
        QString text = QCoreApplication::translate("SerialTrace", d.text);
        for (const std::string &arg : d.args)
            text = text.arg(QString::fromStdString(arg));
        std::fprintf(stderr, "gve-emu: %s\n", text.toLocal8Bit().constData());
        QCoreApplication::exit(3);
        return;
    }
    if (m_replay->finished() && !m_replayEndTold) {
        m_replayEndTold = true;
        std::fprintf(stderr, "gve-emu: %s\n",
                     QCoreApplication::translate("gve-emu", "the trace was played to its end; "
                                                            "further commands get no reply")
                         .toLocal8Bit()
                         .constData());
    }
}

} // namespace frezka::gveemu
