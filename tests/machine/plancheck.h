#pragma once
// Test helpers: build toolpaths in code and replay a UnitProgram independently of the planner,
// checking what every plan must satisfy.

#include "machine/planner.h"
#include "machine/unitmodel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace frezka::machine::test {

// One C/L vector as the unit captures it.
struct Captured
{
    std::array<std::int32_t, 4> d{};
    std::int64_t a = 0, v = 0, b = 0; // A (thousands), V, B at the time of the vector
    bool line = false;
    bool chainEnd = false; // the queue drains after it
    std::uint32_t sourceLine = 0;
};

// Replays a program: modal values, positions, chains. Fails the test on an inconsistency.
inline std::vector<Captured> replay(const UnitProgram &p, bool *vk = nullptr)
{
    std::vector<Captured> out;
    std::int64_t a = -1, v = -1, b = -1;
    Steps4 pos = p.startSteps;
    for (const UnitCommand &c : p.commands) {
        switch (c.op) {
        case UnitOp::Accel:
            a = c.value;
            break;
        case UnitOp::Speed:
            v = c.value;
            break;
        case UnitOp::Brake:
            b = c.value;
            break;
        case UnitOp::SpeedModeVk:
            if (vk)
                *vk = true;
            break;
        case UnitOp::SpeedModeVn:
            if (vk)
                *vk = false;
            break;
        case UnitOp::Vector:
        case UnitOp::Line: {
            bool any = false;
            for (int i = 0; i < 4; ++i) {
                pos[i] += c.d[i];
                any = any || c.d[i] != 0;
            }
            EXPECT_TRUE(any) << "zero-step vector sent, line " << c.sourceLine;
            EXPECT_GT(a, 0);
            EXPECT_GE(v, 10);
            out.push_back({c.d, a, v, c.op == UnitOp::Line ? 0 : b, c.op == UnitOp::Line,
                           c.op == UnitOp::Line, c.sourceLine});
            break;
        }
        default:
            if (!out.empty())
                out.back().chainEnd = true;
            break;
        }
        EXPECT_EQ(c.endSteps, pos) << "endSteps of command " << static_cast<int>(c.op);
    }
    if (!out.empty())
        out.back().chainEnd = true;
    return out;
}

// Checks the integer brake feasibility of every chain exactly as the unit executes it:
// entry e = previous B (0 after a stop), exit x = B (0 at a chain end), in speed units.
inline void expectFeasible(const std::vector<Captured> &vs, bool vk)
{
    std::int64_t e = 0;
    for (std::size_t k = 0; k < vs.size(); ++k) {
        const Captured &c = vs[k];
        const std::int64_t x = c.chainEnd ? 0 : c.b;
        const auto n = static_cast<std::int64_t>(std::floor(speedUnitsLength(c.d, vk) + 1e-9));
        const std::int64_t room = 2 * c.a * 1000 * n;
        EXPECT_LE(e * e, x * x + room) << "cannot brake, vector " << k << " line " << c.sourceLine;
        if (!c.chainEnd) {
            EXPECT_LE(x * x, e * e + room) << "cannot reach B, vector " << k;
            EXPECT_LE(x, c.v) << "B above V, vector " << k;
            EXPECT_GE(x, 10);
        }
        EXPECT_LE(e, c.v) << "entry above V, vector " << k;
        e = x;
    }
}

} // namespace frezka::machine::test
