#pragma once
// LineRunner: drives a SharedLine (several MachineCores, one line) against emulated units on a
// virtual clock, event by event, as SimRunner drives one core (simrunner.h). The far end is a
// VirtualPort over one emulator::Simulation with several units on its wire.

#include "driver/link/sharedline.h"
#include "driver/link/simrunner.h"

#include <functional>
#include <string>

namespace frezka::driver {

class LineRunner
{
public:
    LineRunner(SharedLine &line, VirtualPort &port)
        : m_line(line)
        , m_port(port)
    {}

    void open();
    void unplug(const std::string &why);
    // Runs until done() is true or `limitS` seconds of virtual time have passed.
    bool runUntil(const std::function<bool()> &done, double limitS);
    void runFor(double seconds);
    double now() const { return m_port.now(); }

private:
    void exchange();
    void step(double limit);

    SharedLine &m_line;
    VirtualPort &m_port;
    bool m_open = false;
};

} // namespace frezka::driver
