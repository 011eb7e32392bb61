#pragma once
// A rotary table on its own unit (a second GVE114 on the same line, docs/architecture.md
// "Several units on one line"), driven from the same program as the machine's X Y Z.
//
// The program is planned once for the machine with the rotary unit's A axis (withRotaryA,
// PlanOptions::restAroundA: every toolpath entry that moves A is a chain of its own from rest to
// rest), then split at those block boundaries into two unit programs with sync points
// (splitRotaryA): the machine's unit gets X Y Z (its A component 0), the rotary unit gets A on
// its own A motor (the fourth axis: its counter, home switch IN3 and EEPROM A fields). Blocks
// without A run on the machine's unit as planned, without stops. A block with A motion is a
// barrier on both sides: it starts on both units together, once both have finished what came
// before it, and what follows it starts on either only when both have finished it.
//
// Within such a block each unit runs its part of every vector with the planned A, V and B
// scaled by (its part's major axis / the whole vector's major axis): in VN mode (the planner's
// choice whenever A moves) the trapezoid of each part then takes the same time as the planned
// one, so both units arrive together; the path between the block's ends is only approximately
// the programmed line (the parts are not interpolated jointly: see docs/architecture.md for
// the bound).

#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <cstddef>
#include <string>
#include <vector>

namespace frezka::machine {

// A barrier of a unit program: before command `at` is sent the unit has run everything before
// it, and waits until every unit of the line is at the same barrier. `held`: the unit's block
// starting here moves it, so it is held with H, its block queued, and started with G together
// with the other units (driver/link/synchold.h); else it only waits.
struct SyncPoint
{
    std::size_t at = 0;
    bool held = false;
    friend bool operator==(const SyncPoint &, const SyncPoint &) = default;
};

struct SyncedProgram
{
    UnitProgram program;
    std::vector<SyncPoint> syncs; // in order; several may share an index
};

struct RotarySplit
{
    SyncedProgram machine;  // X Y Z and every event (outputs, spindle, dwells, stops, the end)
    SyncedProgram rotary;   // A only, on the unit's A motor
    std::size_t blocks = 0; // blocks with A motion (each a sync point)
    enum class Error { None, ProbeTurnsA, NotRestAroundA };
    Error errorCode = Error::None;
    std::uint32_t errorLine = 0;
    std::string error; // English; non-empty: the program cannot be split
    bool ok() const { return error.empty(); }
};

// The machine's profile with the rotary unit's A axis (scale, speeds, acceleration, soft
// limits), for planning the whole program: A's soft limits are then checked on the rotary
// unit's profile before the run.
MachineConfig withRotaryA(const MachineConfig &machine, const MachineConfig &rotary);

// Splits a program planned with PlanOptions::restAroundA into the two units' programs; an
// error when a block that turns A holds more than one vector (planned without that option).
RotarySplit splitRotaryA(const UnitProgram &planned);

} // namespace frezka::machine
