#pragma once
// TracingPort: a VirtualPort that records both ways of another into a TraceRecorder on the
// virtual clock, so that a run of SimRunner on the emulator leaves the same trace a session on
// a port would (the traces shipped in tests/driver/traces/ are made this way). The clock it
// shows the driver counts whole nanoseconds, as the trace's times do: replayed on
// emulator::TraceReplay's clock, the driver sees the very same instants again (a virtual clock
// makes ties, e.g. a poll timer due just as a reply arrives, and they must fall the same way).

#include "driver/link/simrunner.h"
#include "driver/link/tracerecorder.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace frezka::driver {

class TracingPort : public VirtualPort
{
public:
    TracingPort(VirtualPort &inner, TraceRecorder &recorder)
        : m_inner(inner)
        , m_recorder(recorder)
    {}

    void write(std::string_view bytes) override
    {
        m_recorder.record(emulator::TraceDirection::ToUnit, bytes, now());
        m_inner.write(bytes);
    }
    std::string read() override
    {
        std::string in = m_inner.read();
        if (!in.empty())
            m_recorder.record(emulator::TraceDirection::ToPc, in, now());
        return in;
    }
    double now() const override { return static_cast<double>(m_nowNs) * 1e-9; }
    double nextEventIn() const override
    {
        const double s = m_inner.nextEventIn();
        return std::isfinite(s) ? std::ceil(s * 1e9) * 1e-9 : s;
    }
    void advance(double seconds) override
    {
        const std::int64_t ns = std::max<std::int64_t>(0, std::llround(seconds * 1e9));
        m_nowNs += ns;
        m_inner.advance(static_cast<double>(ns) * 1e-9);
    }

private:
    VirtualPort &m_inner;
    TraceRecorder &m_recorder;
    std::int64_t m_nowNs = 0;
};

} // namespace frezka::driver
