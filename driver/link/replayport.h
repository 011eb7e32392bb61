#pragma once
// ReplayPort: a recorded unit (emulator::TraceReplay over a serial trace) as the far end of a
// virtual-clock link, for SimRunner: the regression helper drives the driver against it.

#include "driver/emulator/tracereplay.h"
#include "driver/link/simrunner.h"

namespace frezka::driver {

class ReplayPort : public VirtualPort
{
public:
    // freePolls: see emulator::TraceReplay.
    explicit ReplayPort(emulator::SerialTrace trace, bool freePolls = false)
        : m_replay(std::move(trace), freePolls)
    {}

    void write(std::string_view bytes) override { m_replay.pcWrite(bytes); }
    std::string read() override { return m_replay.pcRead(); }
    double now() const override { return m_replay.now(); }
    double nextEventIn() const override { return m_replay.nextEventIn(); }
    void advance(double seconds) override { m_replay.advance(seconds); }

    const emulator::TraceReplay &replay() const { return m_replay; }

private:
    emulator::TraceReplay m_replay;
};

} // namespace frezka::driver
