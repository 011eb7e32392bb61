#include "emulatorrun.h"

#include "driver/emulator/unit.h"
#include "machine/unitmodel.h"
#include "machine/unitwire.h"
#include "protocol/command.h"

#include <algorithm>
#include <cmath>

namespace frezka::machine::test {

namespace {

class Feeder
{
public:
    Feeder(const MachineConfig &config)
        : m_unit({.variant = config.unit.variant,
                  .maxPulseRate = config.unit.maxPulseRate,
                  .trace = true})
    {}

    emulator::Unit &unit() { return m_unit; }

    // Sends one command; a full queue (code 1 for C/L) waits for the next event and retries.
    bool send(const protocol::Command &c, std::string *error)
    {
        const std::string bytes = protocol::encode(c, false);
        for (;;) {
            m_unit.receive(bytes);
            const std::string reply = m_unit.takeTransmit();
            if (!reply.empty() && reply[0] == '0')
                return true;
            const bool retry = !reply.empty() && reply[0] == '1' &&
                               (c.op == protocol::Op::Vector || c.op == protocol::Op::Line);
            if (!retry) {
                *error = "'" + protocol::encodeBody(c) + "' answered '" + reply + "'";
                return false;
            }
            step();
        }
    }

    void waitIdle()
    {
        while (m_unit.queueLength() > 0)
            step();
    }

    void wait(double seconds) { m_unit.advance(seconds); }

private:
    // To the next event: advancing by exactly nextEventIn() always takes the event.
    void step()
    {
        const double dt = m_unit.nextEventIn();
        m_unit.advance(std::isfinite(dt) ? dt : 1e-3);
    }

    emulator::Unit m_unit;
};

struct Vertex
{
    std::array<std::int32_t, 4> d;
    Steps4 end;
};

} // namespace

JumpFigures measureJumps(const std::vector<emulator::TracePoint> &trace, const UnitProgram &p,
                         const MachineConfig &config)
{
    JumpFigures run;
    bool vk = false;
    std::vector<Vertex> vs;
    for (const UnitCommand &c : p.commands) {
        if (c.op == UnitOp::SpeedModeVk || c.op == UnitOp::SpeedModeVn)
            vk = c.op == UnitOp::SpeedModeVk;
        if (c.op == UnitOp::Vector || c.op == UnitOp::Line)
            vs.push_back({c.d, c.endSteps});
    }
    std::size_t j = 0;
    for (const emulator::TracePoint &t : trace) {
        if (j >= vs.size())
            break;
        bool at = true;
        for (int i = 0; i < 4; ++i)
            at = at && t.position[i] + p.startSteps[i] == vs[j].end[i];
        if (!at)
            continue;
        const double v = t.pathSpeedPulsesPerS;
        if (v > 0 && j + 1 < vs.size()) {
            ++run.vertices;
            const double l0 = speedUnitsLength(vs[j].d, vk), l1 = speedUnitsLength(vs[j + 1].d, vk);
            bool over = false;
            for (int i = 0; i < 4; ++i) {
                const AxisConfig &a = config.axes[static_cast<std::size_t>(i)];
                const double before = v * vs[j].d[i] / l0, after = v * vs[j + 1].d[i] / l1;
                const double jump = std::abs(before - after) / a.stepsPerMm;
                run.maxJumpMmPerS = std::max(run.maxJumpMmPerS, jump);
                const double ratio = a.maxJumpMmPerS > 0 ? jump / a.maxJumpMmPerS : 0;
                run.maxRatio = std::max(run.maxRatio, ratio);
                over = over || ratio > 1 + 1e-9;
            }
            run.overLimit += over ? 1 : 0;
        }
        ++j;
    }
    return run;
}

namespace {} // namespace

EmulatorRun runOnEmulator(const UnitProgram &program, const MachineConfig &config)
{
    EmulatorRun run;
    Feeder feeder(config);
    emulator::Unit &unit = feeder.unit();
    if (protocol::variantInfo(config.unit.variant).hasMpg &&
        !feeder.send(protocol::cmd::mpgOff(), &run.error))
        return run;
    const double t0 = unit.now();
    run.plannedStops = plannedRestarts(program);
    Steps4 last = program.startSteps;
    for (const UnitCommand &c : program.commands) {
        if (const auto wire = wireCommand(c, program.axisCount)) {
            if (!feeder.send(*wire, &run.error))
                return run;
            if (c.op == UnitOp::Vector || c.op == UnitOp::Line)
                last = c.endSteps;
            continue;
        }
        feeder.waitIdle();
        if (c.op == UnitOp::Dwell)
            feeder.wait(static_cast<double>(c.value) / 1000.0);
        if (c.op == UnitOp::Probe) {
            run.error = "probe moves are not run by this benchmark";
            return run;
        }
    }
    feeder.waitIdle();
    run.jobS = unit.now() - t0;
    const emulator::Stats stats = unit.stats();
    run.vectors = stats.motion.vectorsExecuted;
    run.brakeViolations = stats.motion.brakeViolations;
    run.worstBrakeExcess = stats.motion.worstBrakeExcessPulsesPerS;
    run.starvationStops = stats.motion.starvationStops;
    const auto pos = unit.position();
    run.countersMatch = true;
    for (int i = 0; i < 4; ++i)
        run.countersMatch = run.countersMatch && pos[i] + program.startSteps[i] == last[i];
    const JumpFigures jumps = measureJumps(unit.trace(), program, config);
    run.vertices = jumps.vertices;
    run.jumpOverLimit = jumps.overLimit;
    run.maxJumpMmPerS = jumps.maxJumpMmPerS;
    run.maxJumpRatio = jumps.maxRatio;
    return run;
}

} // namespace frezka::machine::test
