#pragma once
// SimRunner: drives a MachineCore against a unit on a virtual clock, event by event.
//
// Nothing sleeps and nothing waits for wall time: the runner advances the far end (the emulator
// with its wire model) straight to the next thing that can happen — a byte arriving, the unit's
// own next event, or the core's next deadline — so a job of minutes runs in milliseconds,
// deterministically. Used by tests, benchmarks and `frezka-cli run --clock virtual`.

#include "driver/link/machinecore.h"

#include <functional>
#include <string>
#include <string_view>

namespace frezka::driver {

// The unit end of a virtual-clock link.
class VirtualPort
{
public:
    virtual ~VirtualPort() = default;
    // Bytes from the PC, handed to the wire at now().
    virtual void write(std::string_view bytes) = 0;
    // Bytes that have reached the PC by now().
    virtual std::string read() = 0;
    virtual double now() const = 0;
    // Seconds until the far end changes by itself (a byte arrives somewhere, motion event);
    // infinity when it would wait forever.
    virtual double nextEventIn() const = 0;
    virtual void advance(double seconds) = 0;
};

class SimRunner
{
public:
    SimRunner(MachineCore &core, VirtualPort &port)
        : m_core(core)
        , m_port(port)
    {}

    // Opens the link (the core starts its connect sequence).
    void open();
    // Closes the link as an unplugged converter would.
    void unplug(const std::string &why);
    // Runs until done() is true or `limitS` seconds of virtual time have passed.
    // Returns done() at the end.
    bool runUntil(const std::function<bool()> &done, double limitS);
    // Runs for exactly `seconds` of virtual time.
    void runFor(double seconds);
    double now() const { return m_port.now(); }

private:
    void exchange();
    void step(double limit);

    MachineCore &m_core;
    VirtualPort &m_port;
    bool m_open = false;
};

} // namespace frezka::driver
