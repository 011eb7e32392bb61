#pragma once
// Helpers shared by the emulator tests.

#include "driver/emulator/unit.h"
#include "protocol/checksum.h"

#include <string>
#include <string_view>

namespace frezka::emulator::test {

using protocol::Variant;

// Sends bytes, returns what the unit sent at once.
inline std::string ask(Unit &unit, std::string_view bytes)
{
    unit.receive(bytes);
    return unit.takeTransmit();
}

// A command with its checksum: "!0A100" -> "!0A100,4F\r".
inline std::string withChecksum(std::string_view command)
{
    std::string text(command);
    text += ',';
    return text + protocol::hexByte(protocol::checksum(text)) + "\r";
}

// Runs the clock until nothing is left to happen (or maxS of virtual time passed).
inline void runUntilIdle(Unit &unit, double maxS = 1e6)
{
    const double end = unit.now() + maxS;
    while (unit.nextEventIn() < kNever && unit.now() < end)
        unit.advance(std::min(unit.nextEventIn(), end - unit.now()));
}

inline UnitOptions optionsFor(Variant v)
{
    UnitOptions o;
    o.variant = v;
    return o;
}

// A unit after reset with the MPG switched off (vectors accepted).
inline Unit readyUnit(Variant v = Variant::Gve64)
{
    Unit unit(optionsFor(v));
    if (unit.variantInfo().hasMpg)
        ask(unit, "!0Y-\r");
    return unit;
}

} // namespace frezka::emulator::test
