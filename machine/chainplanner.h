#pragma once
// Internal to frezka_machine: vertex caps, the integer backward/forward passes and the
// time-optimal bound for a run of moves that starts and ends at rest (docs/planner.md §3-§5).

#include "machine/machineconfig.h"
#include "machine/planner.h"
#include "machine/unitprogram.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace frezka::machine::detail {

// What the program's modes give a move: its feed, the junction deviation in force, rapid or
// not, exact stop. Consecutive moves mostly share them (modal G-code words), so a run keeps each
// once (Moves) and its moves an index: 16 bytes a move less (issue 17: a run of 5 M moves).
struct MoveModes
{
    double feedMmPerS = 0;          // requested path speed; ignored for rapids
    double junctionDeviationMm = 0; // in force for the vertex before the move
    bool rapid = false;
    bool stopAfter = false; // the move must end at rest (G61 exact stop)
};

// One non-zero step vector of the path, as the walk over the toolpath produced it. Where it
// ends in absolute steps is the run's start plus the moves up to it (Planner::flush): 32 bytes
// less a move than keeping it (issue 17: a run of 5 M moves); its modes are its run's
// (Moves::modes).
struct Move
{
    std::array<std::int32_t, 4> d{};   // relative steps (difference of rounded absolutes)
    std::array<double, 4> pathDelta{}; // the intended mm (deg) displacement, before rounding
    std::uint32_t line = 0;
    std::uint32_t modes = 0; // Moves: index of its modes
};
static_assert(sizeof(Move) <= 56, "a Move is held for every move of a run");

// The moves of a run with their modes, each distinct run of equal modes kept once (a program
// whose feed changes at every move keeps one a move: 24 bytes more than the 16 saved).
class Moves
{
public:
    // Appends m with its modes (m.modes is set here).
    void push_back(Move m, const MoveModes &modes);
    std::size_t size() const { return m_moves.size(); }
    bool empty() const { return m_moves.empty(); }
    const Move &operator[](std::size_t k) const { return m_moves[k]; }
    const Move &back() const { return m_moves.back(); }
    const MoveModes &modes(std::size_t k) const { return m_modes[m_moves[k].modes]; }
    std::size_t capacity() const { return m_moves.capacity(); }
    void reserve(std::size_t n) { m_moves.reserve(n); }
    void clear();
    void shrink_to_fit() { m_moves.shrink_to_fit(); }

private:
    std::vector<Move> m_moves;
    std::vector<MoveModes> m_modes;
};

// The speeds of moves[k] as it goes to the unit (its steps and line stay in the Move). 32-bit:
// V and B are at most the unit's pulse rate, A at most kMaxAccel (below 2^17), so A and the two
// flags share 32 bits (12 bytes a move, not 32).
struct PlannedVector
{
    std::int32_t speed = 0;      // V, pulses/s in the mode's units
    std::int32_t brake = 0;      // B, pulses/s; the chain's last vector: see chainEnd
    std::int32_t accel : 30 = 0; // A, thousands of pulses/s²
    bool chainEnd : 1 = false;   // the unit must stop after this vector (queue drains)
    bool line : 1 = false;       // send as L (stand-alone, from and to rest), not C
};
static_assert(sizeof(PlannedVector) == 12, "a PlannedVector is held for every move of a run");

// A feed move whose programmed feed is above what the axes (or the unit's pulse rate) allow in
// its direction: the plan runs it at the allowed speed.
struct FeedCap
{
    std::uint32_t line = 0;
    double askedMmPerS = 0;
    double runMmPerS = 0;
    char limit = 'X'; // the axis whose maximum speed sets it, or 'P' for the unit's pulse rate
    double limitMmPerS = 0; // that axis's maximum (P: the pulse rate in mm/s along the move)
};

struct RunOutcome
{
    std::vector<PlannedVector> vectors;   // one per move, in order
    std::vector<std::uint32_t> slowLines; // lines whose feed is below the unit's 10 pulses/s
    FeedCap firstFeedCap;                 // the first move whose feed is capped (line 0: none)
    std::size_t feedCapLines = 0;         // lines with a capped feed (consecutive moves: once)
    std::size_t chains = 0;
    int plans = 0;                       // plans of the run (the first and the pace's re-plans)
    double boundS = 0;                   // time-optimal bound of these moves
    double maxJumpMmPerS = 0;            // largest per-axis speed step at a vertex of the plan
    double maxJumpRatio = 0;             // largest speed step / axis limit
    std::size_t jumpOverLimit = 0;       // vertices with a step over an axis limit
    double maxCurveAccelRatio = 0;       // largest axis acceleration through a turn / limit
    std::size_t curveAccelOverLimit = 0; // vertices turning faster than the axes accelerate
};

// Plans moves that start and end at rest. vk: speeds are VK path speeds (else VN major axis).
RunOutcome planRun(const Moves &moves, const MachineConfig &config, const PlanOptions &options,
                   bool vk);

} // namespace frezka::machine::detail
