// Two GVE114 units on one line, each with its own MachineCore, under one SharedLine arbiter
// (driver/link/sharedline.h) against the in-process emulator's shared wire: two jobs run at once
// to exact counters, and a reply is never taken for the other unit's, neither a unit answering
// out of turn nor a command whose address byte was damaged on the way.

#include "simfixture.h"

#include "driver/link/linerunner.h"
#include "driver/link/sharedline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <memory>

namespace frezka::driver::test {
namespace {

using protocol::Variant;

// The PC end of the line with test hooks: a unit talking out of turn at a chosen time.
class HookedPort : public VirtualPort
{
public:
    explicit HookedPort(EmulatorPort &port)
        : m_port(port)
    {}
    void write(std::string_view bytes) override
    {
        if (onWrite)
            onWrite(bytes);
        m_port.write(bytes);
    }
    std::string read() override { return m_port.read(); }
    double now() const override { return m_port.now(); }
    double nextEventIn() const override
    {
        const double n = m_port.nextEventIn();
        return m_injectAt ? std::max(0.0, std::min(n, *m_injectAt - now())) : n;
    }
    void advance(double seconds) override
    {
        if (m_injectAt && now() + seconds >= *m_injectAt) {
            const double before = std::max(0.0, *m_injectAt - now());
            m_port.advance(before);
            m_port.simulation().unitSideWrite(m_inject);
            m_injectAt.reset();
            ++injected;
            seconds -= before;
        }
        m_port.advance(seconds);
    }
    // `bytes` enter the line towards the PC at `atS` (a unit answering out of turn).
    void injectAt(double atS, std::string bytes)
    {
        m_injectAt = atS;
        m_inject = std::move(bytes);
    }
    std::function<void(std::string_view)> onWrite;
    int injected = 0;

private:
    EmulatorPort &m_port;
    std::optional<double> m_injectAt;
    std::string m_inject;
};

CoreOptions optionsFor(int address)
{
    CoreOptions o;
    o.link.sharedLine = true;
    o.link.unitAddress = address;
    o.returnToPathAutomatically = true;
    return o;
}

std::vector<emulator::UnitOptions> unitsFor(const machine::MachineConfig &config)
{
    emulator::UnitOptions a = unitOptionsFor(config);
    emulator::UnitOptions b = a;
    b.address = 1;
    b.spindleAddress = false; // the spindle at 7 is unit 0's
    return {a, b};
}

struct TwoUnits
{
    explicit TwoUnits(WireOptions wire = {}, SharedLineOptions lineOptions = {})
        : config(machine::defaultMachineConfig(Variant::Gve114))
        , port(unitsFor(config), wire)
        , hooked(port)
        , core0(config, optionsFor(0))
        , core1(config, optionsFor(1))
        , line({&core0, &core1}, lineOptions)
        , runner(line, hooked)
    {
        for (MachineCore *core : {&core0, &core1}) {
            core->onError = [this, core](const MachineError &e) {
                errors.push_back((core == &core0 ? "unit 0: " : "unit 1: ") + e.message);
            };
        }
        core0.onJobFinished = [this](bool ok) { finished0.push_back(ok); };
        core1.onJobFinished = [this](bool ok) { finished1.push_back(ok); };
        line.onLog = [this](const std::string &text) { lineLog.push_back(text); };
    }
    bool connect()
    {
        runner.open();
        return runner.runUntil(
                   [this] {
                       return core0.state().mode != MachineMode::Connecting &&
                              core1.state().mode != MachineMode::Connecting;
                   },
                   60) &&
               core0.state().mode == MachineMode::Idle && core1.state().mode == MachineMode::Idle;
    }
    // Runs both jobs to their ends; true when both finished well. Notes whether the two units
    // ever moved at the same time.
    bool runBoth(const machine::UnitProgram &a, const machine::UnitProgram &b)
    {
        if (core0.run(a, runner.now()) || core1.run(b, runner.now()))
            return false;
        runner.runUntil(
            [this] {
                bothMoved = bothMoved || (port.simulation().unit(0).isMoving() &&
                                          port.simulation().unit(1).isMoving());
                return !finished0.empty() && !finished1.empty();
            },
            600);
        return finished0 == std::vector<bool>{true} && finished1 == std::vector<bool>{true};
    }
    std::string why() const
    {
        std::string s = "unit 0 " + std::string(machineModeName(core0.state().mode)) + ", unit 1 " +
                        machineModeName(core1.state().mode) + "\n";
        for (const std::string &e : errors)
            s += e + "\n";
        for (std::size_t i = lineLog.size() > 10 ? lineLog.size() - 10 : 0; i < lineLog.size(); ++i)
            s += lineLog[i] + "\n";
        return s;
    }

    machine::MachineConfig config;
    EmulatorPort port;
    HookedPort hooked;
    MachineCore core0;
    MachineCore core1;
    SharedLine line;
    LineRunner runner;
    std::vector<std::string> errors;
    std::vector<std::string> lineLog;
    std::vector<bool> finished0, finished1;
    bool bothMoved = false;
};

machine::Steps4 endOf(const machine::UnitProgram &p)
{
    return p.commands.back().endSteps;
}

std::int64_t vectorsOf(const machine::UnitProgram &p)
{
    return std::count_if(p.commands.begin(), p.commands.end(),
                         [](const auto &c) { return c.op == machine::UnitOp::Vector; });
}

// Both units' counters and vector counts are exactly their own programs'.
void expectExact(TwoUnits &t, const machine::UnitProgram &a, const machine::UnitProgram &b)
{
    const emulator::Unit &u0 = t.port.simulation().unit(0);
    const emulator::Unit &u1 = t.port.simulation().unit(1);
    const auto ea = endOf(a), eb = endOf(b);
    EXPECT_EQ(u0.position(), (std::array<std::int64_t, 4>{ea[0], ea[1], ea[2], ea[3]}));
    EXPECT_EQ(u1.position(), (std::array<std::int64_t, 4>{eb[0], eb[1], eb[2], eb[3]}));
    EXPECT_EQ(u0.stats().motion.vectorsExecuted, vectorsOf(a));
    EXPECT_EQ(u1.stats().motion.vectorsExecuted, vectorsOf(b));
    EXPECT_EQ(t.core0.jobReport().vectors, vectorsOf(a));
    EXPECT_EQ(t.core1.jobReport().vectors, vectorsOf(b));
}

machine::UnitProgram programA()
{
    return denseProgram(900, 4, 20000, 20000, 60);
}

machine::UnitProgram programB()
{
    auto p = denseProgram(700, 4, 12000, 12000, 90);
    machine::Steps4 at = p.startSteps;
    for (std::size_t i = 0; i < p.commands.size(); ++i) {
        machine::UnitCommand c = p.commands[i];
        if (c.op == machine::UnitOp::Vector)
            c.d = {-c.d[1], c.d[0], 0, 3}; // another shape, with A
        for (int k = 0; k < 4; ++k)
            at[k] += c.d[k];
        c.endSteps = at;
        p.commands.set(i, c);
    }
    return p;
}

} // namespace

TEST(SharedLine, TwoJobsAtOnceToExactCounters)
{
    TwoUnits t;
    ASSERT_TRUE(t.connect()) << t.why();
    EXPECT_EQ(t.core0.state().firmware.rfind("IP114", 0), 0u) << t.core0.state().firmware;
    EXPECT_EQ(t.core1.state().firmware.rfind("IP114", 0), 0u) << t.core1.state().firmware;
    const auto a = programA(), b = programB();
    ASSERT_TRUE(t.runBoth(a, b)) << t.why();
    EXPECT_TRUE(t.bothMoved); // at once, not one after the other
    expectExact(t, a, b);
    EXPECT_TRUE(t.errors.empty()) << t.why();
    // Each unit held the line for part of the time; the line's share is their sum.
    const double now = t.runner.now();
    const double s0 = t.line.unitShare(0, now), s1 = t.line.unitShare(1, now);
    EXPECT_GT(s0, 0);
    EXPECT_GT(s1, 0);
    EXPECT_NEAR(t.line.lineShare(now), s0 + s1, 1e-9);
    EXPECT_GT(t.line.stats().units[0].exchanges, 10);
    EXPECT_GT(t.line.stats().units[1].exchanges, 10);
    // Every command went to its own address: neither unit saw a line it had to refuse.
    EXPECT_EQ(t.port.simulation().unit(0).stats().checksumErrors, 0);
    EXPECT_EQ(t.port.simulation().unit(1).stats().checksumErrors, 0);
}

// Unit 0 answers "queue full" ("1") while unit 1 is addressed. Taken for unit 1's reply it
// would make unit 1's core send an accepted vector again (or, landing in a later exchange, make
// another command look refused): the counters would be off. The two replies come within the
// quiet time, so unit 1's core gets them as one garbled line and recovers with '@' / '>' on its
// own address. Without latency the stray reply follows unit 1's own; with 3 ms each way (and a
// quiet time above the round trip) it comes first.
void runOutOfTurn(double latencyS, double quietS)
{
    WireOptions wire;
    wire.latencyS = latencyS;
    SharedLineOptions lineOptions;
    lineOptions.quietS = quietS;
    TwoUnits t(wire, lineOptions);
    ASSERT_TRUE(t.connect()) << t.why();
    const auto a = programA(), b = programB();
    int writesToUnit1 = 0;
    const double byteS = 10.0 / 115200;
    t.hooked.onWrite = [&](std::string_view bytes) {
        if (!bytes.starts_with("!1"))
            return;
        // Several times during the jobs, once unit 1's command has left the PC.
        if (++writesToUnit1 % 20 == 10)
            t.hooked.injectAt(t.runner.now() + (bytes.size() + 2) * byteS, "1,5D\r");
    };
    ASSERT_TRUE(t.runBoth(a, b)) << t.why();
    EXPECT_GT(t.hooked.injected, 3);
    EXPECT_GT(t.line.stats().units[1].collisions, 0);
    EXPECT_GT(t.core1.engine().stats().recovered + t.core1.engine().stats().resent, 0);
    expectExact(t, a, b);
}

TEST(SharedLine, AReplyOutOfTurnAfterTheAddressedUnitsIsNotTaken)
{
    runOutOfTurn(0, 0.002);
}

TEST(SharedLine, AReplyOutOfTurnBeforeTheAddressedUnitsIsNotTaken)
{
    runOutOfTurn(0.003, 0.008);
}

// The same stray reply while the addressed unit's command is still on the wire: it cannot be
// its reply (no unit answers before it has heard the command) and is taken by nobody.
TEST(SharedLine, AReplyBeforeTheCommandHasLeftIsNobodys)
{
    TwoUnits t;
    ASSERT_TRUE(t.connect()) << t.why();
    const auto a = programA(), b = programB();
    int writes = 0;
    t.hooked.onWrite = [&](std::string_view bytes) {
        if (bytes.starts_with("!1") && ++writes % 40 == 20)
            t.hooked.injectAt(t.runner.now(), "1,5D\r");
    };
    ASSERT_TRUE(t.runBoth(a, b)) << t.why();
    EXPECT_GT(t.hooked.injected, 3);
    EXPECT_GE(t.line.stats().earlyLines, t.hooked.injected);
    expectExact(t, a, b);
}

// A command for unit 1 whose address byte is damaged on the way: once into unit 0's address
// (unit 0 refuses it, its checksum does not fit, and answers 4), once into no address at all
// (nobody answers). Unit 1's core learns with '@' that its unit did not get it and sends it
// again; unit 0 runs nothing of it.
TEST(SharedLine, ADamagedAddressByteRunsOnNeitherUnit)
{
    TwoUnits t;
    ASSERT_TRUE(t.connect()) << t.why();
    const auto a = programA(), b = programB();
    int writes = 0;
    int damaged = 0;
    t.port.tamper = [&](std::string_view bytes) {
        std::string out(bytes);
        if (out.starts_with("!1") && ++writes % 25 == 10) {
            out[1] = (damaged++ % 2 == 0) ? '0' : static_cast<char>('1' ^ 0x40); // '0' or 'q'
        }
        return out;
    };
    ASSERT_TRUE(t.runBoth(a, b)) << t.why();
    EXPECT_GT(damaged, 4);
    EXPECT_GT(t.port.simulation().unit(0).stats().checksumErrors, 0);
    EXPECT_GT(t.core1.engine().stats().resent + t.core1.engine().stats().recovered, 0);
    expectExact(t, a, b);
}

} // namespace frezka::driver::test

namespace frezka::driver::test {

// A unit alone on its line at another address (the profile's unit.address): the driver sends
// every command to it and the built-in emulator answers on it; a job runs to exact counters.
TEST(UnitAddress, AUnitAloneAtAnotherAddressRunsItsJob)
{
    machine::MachineConfig config = machine::defaultMachineConfig(Variant::Gve114);
    config.unit.address = 3;
    EmulatorPort port(unitOptionsFor(config), {});
    EXPECT_EQ(port.unit().options().address, 3);
    MachineCore core(config, {});
    std::vector<std::string> sent;
    core.onLog = [&sent](const std::string &line) {
        if (line.rfind("> ", 0) == 0)
            sent.push_back(line);
    };
    bool finished = false;
    core.onJobFinished = [&finished](bool ok) { finished = ok; };
    SimRunner runner(core, port);
    runner.open();
    ASSERT_TRUE(runner.runUntil([&] { return core.state().mode == MachineMode::Idle; }, 30));
    const auto program = programA();
    ASSERT_FALSE(core.run(program, runner.now()));
    ASSERT_TRUE(runner.runUntil([&] { return finished; }, 600));
    const auto end = endOf(program);
    EXPECT_EQ(port.unit().position(),
              (std::array<std::int64_t, 4>{end[0], end[1], end[2], end[3]}));
    EXPECT_EQ(port.unit().stats().motion.vectorsExecuted, vectorsOf(program));
    ASSERT_FALSE(sent.empty());
    for (const std::string &line : sent)
        EXPECT_TRUE(line.find("!0") == std::string::npos &&
                    (line.find("!3") != std::string::npos || line.find("!7") != std::string::npos))
            << line;
}

} // namespace frezka::driver::test
