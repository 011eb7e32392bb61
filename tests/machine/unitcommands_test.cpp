// UnitCommands (issue 17): the compact store gives back every command exactly as stored, the
// ones that fit a 24-byte record and the ones kept whole, through every change; a planned
// program takes at most 26 bytes a command.
#include "machine/unitcommands.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace frezka::machine {
namespace {

// Commands as the planner makes them (ends summed from d), and ones that do not fit a record:
// a probe with its kind, a vector with a value, an output with steps, an end that is not the
// sum, values past 32 bits.
std::vector<UnitCommand> mixedCommands(unsigned seed, std::size_t n)
{
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> step(-100000, 100000), kind(0, 9);
    std::vector<UnitCommand> out;
    Steps4 end{123456789012LL, -5, 7, 0};
    for (std::size_t i = 0; i < n; ++i) {
        UnitCommand c;
        c.sourceLine = std::uint32_t(i * 3 + 1);
        const int k = kind(rng);
        if (k < 5) {
            c.op = k == 0 ? UnitOp::Line : UnitOp::Vector;
            c.d = {step(rng), step(rng), step(rng), k == 1 ? step(rng) : 0};
        } else if (k == 5) {
            c.op = UnitOp::Probe;
            c.d = {0, 0, -step(rng), 0};
            c.aux = 2;
        } else if (k == 6) {
            c.op = UnitOp::Speed;
            c.value = std::int64_t(step(rng)) * 100000LL; // past 32 bits, negative too
        } else if (k == 7) {
            c.op = UnitOp::OperatorStop;
            c.value = 2;
            c.aux = -17;
        } else if (k == 8) {
            c.op = UnitOp::Output;
            c.value = 0xFE;
            c.d = {1, 0, 0, 0}; // steps on a command that has none: kept whole
        } else {
            c.op = UnitOp::Vector;
            c.d = {step(rng), 0, 0, 0};
            c.value = 9; // a value on a vector: kept whole
        }
        for (std::size_t a = 0; a < 4; ++a)
            end[a] += c.op == UnitOp::Line || c.op == UnitOp::Vector || c.op == UnitOp::Probe
                          ? c.d[a]
                          : 0;
        if (i % 37 == 5)
            end[1] += 11; // an end that is not the sum: kept whole, the next ones follow it
        c.endSteps = end;
        out.push_back(c);
    }
    return out;
}

void expectSame(const UnitCommands &store, const std::vector<UnitCommand> &expected)
{
    ASSERT_EQ(store.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        ASSERT_EQ(store[i], expected[i]) << "command " << i;
        ASSERT_EQ(store.endSteps(i), expected[i].endSteps) << "command " << i;
    }
    std::size_t i = 0;
    for (const UnitCommand &c : store) // walked: each end from the one before
        ASSERT_EQ(c, expected[i++]);
    for (std::size_t from : {std::size_t(0), expected.size() / 3, expected.size() - 1}) {
        auto it = store.begin() + std::ptrdiff_t(from); // jumped: from the mark before
        for (std::size_t k = from; k < std::min(expected.size(), from + 40); ++k, ++it)
            ASSERT_EQ(*it, expected[k]) << "from " << from << ", command " << k;
    }
}

TEST(UnitCommands, GivesBackEveryCommandAsStored)
{
    for (unsigned seed = 1; seed <= 5; ++seed) {
        const std::vector<UnitCommand> commands = mixedCommands(seed, 1000 + seed);
        UnitCommands store;
        for (const UnitCommand &c : commands)
            store.push_back(c);
        expectSame(store, commands);
        EXPECT_EQ(store.toVector(), commands);
        EXPECT_EQ(UnitCommands(commands), store);
        EXPECT_EQ(store.front(), commands.front());
        EXPECT_EQ(store.back(), commands.back());
    }
}

TEST(UnitCommands, ChangesInTheMiddleKeepTheOthers)
{
    std::vector<UnitCommand> expected = mixedCommands(7, 200);
    UnitCommands store(expected);
    UnitCommand speed;
    speed.op = UnitOp::Speed;
    speed.value = 5;
    speed.sourceLine = 7;
    store.insert(store.begin(), speed);
    expected.insert(expected.begin(), speed);
    expectSame(store, expected);
    store.erase(store.begin() + 50);
    expected.erase(expected.begin() + 50);
    expectSame(store, expected);
    UnitCommand changed = store[60];
    changed.sourceLine = 99999;
    store.set(60, changed);
    expected[60] = changed;
    expectSame(store, expected);
    for (int k = 0; k < 40; ++k) { // across marks, through kept-whole commands
        store.pop_back();
        expected.pop_back();
        expectSame(store, expected);
    }
    const auto isVector = [](const UnitCommand &c) { return c.op == UnitOp::Vector; };
    const std::size_t removed = erase_if(store, isVector);
    EXPECT_EQ(removed, std::size_t(std::erase_if(expected, isVector)));
    expectSame(store, expected);
    store.push_back(speed);
    expected.push_back(speed);
    expectSame(store, expected);
    EXPECT_NE(store, UnitCommands(mixedCommands(8, 200)));
}

// The spiral of bench_gui_load, planned: every command a 24-byte record, the marks two bytes a
// command (72 bytes a command as a std::vector<UnitCommand>).
TEST(UnitCommands, APlannedProgramTakesAtMost26BytesACommand)
{
    std::string text = "G21 G90 G17 G94 F3000\nG0 X50 Y50 Z-5\nG1 Z-6\n";
    for (int i = 1; i <= 20000; ++i) {
        const double r = 0.5 + i * 0.002, a = i * 0.05;
        text += "G1 X" + std::to_string(50 + r * std::cos(a)) + " Y" +
                std::to_string(50 + r * std::sin(a)) + "\n";
    }
    text += "M2\n";
    const gcode::Result g = gcode::interpretText(text, {});
    ASSERT_TRUE(g.ok());
    const PlanResult p = plan(g.toolpath, defaultMachineConfig(protocol::Variant::Gve64));
    ASSERT_TRUE(p.ok());
    const UnitCommands &commands = p.program.commands;
    ASSERT_GT(commands.size(), 20000u);
    UnitCommands tight(commands.toVector());
    tight.shrink_to_fit();
    EXPECT_LE(tight.bytes(), commands.size() * 26 + 64) << commands.size() << " commands";
    EXPECT_EQ(tight, commands);
    EXPECT_EQ(commands.back().endSteps, commands.endSteps(commands.size() - 1));
}

} // namespace
} // namespace frezka::machine
