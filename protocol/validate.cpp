// validate(): every documented argument range of docs/gve-protocol.md in one place, so that a
// command the unit would refuse (code 4 or 5) is refused before it is sent.

#include "command.h"

#include <cmath>
#include <string>

namespace frezka::protocol {
namespace {

constexpr std::int64_t kStepsMax = 2147483647; // counters and components: +-(2^31 - 1)
constexpr std::int64_t kUint32Max = 4294967295;

using P = CommandProblem;

// A refusal of `c`: its kind, the problem and the values the problem names; the English message
// from them.
CommandCheck fail(CommandError e, P problem, const Command &c, std::string unit = {},
                  std::string what = {})
{
    CommandCheck check;
    check.error = e;
    check.problem = problem;
    check.command = encodeBody(c);
    check.unit = std::move(unit);
    check.what = std::move(what);
    check.message = commandProblemText(check);
    return check;
}

CommandCheck range(const Command &c, std::int64_t v, std::int64_t lo, std::int64_t hi,
                   const char *name)
{
    if (v >= lo && v <= hi)
        return {};
    CommandCheck check;
    check.error = CommandError::OutOfRange;
    check.problem = P::ValueOutOfRange;
    check.command = encodeBody(c);
    check.what = name;
    check.value = v;
    check.low = lo;
    check.high = hi;
    check.message = commandProblemText(check);
    return check;
}

bool allowedOnAddress7(Op op)
{
    switch (op) {
    case Op::Version:
    case Op::Identify:
    case Op::Repeat:
    case Op::Index:
    case Op::Jump:
    case Op::ChecksumOn:
    case Op::ChecksumOff:
    case Op::EepromReadByte:
    case Op::EepromWriteByte:
    case Op::EepromReadFloat:
    case Op::EepromReadUint:
    case Op::EepromWriteFloat:
    case Op::EepromWriteUint:
    case Op::SpindleSpeed:
        return true;
    default:
        return false;
    }
}

CommandCheck checkAddress(const Command &c, const VariantInfo &info)
{
    if (c.address > 7)
        return fail(CommandError::BadAddress, P::AddressRange, c);
    if (c.address == 7) {
        if (!info.hasSpindleAddress7)
            return fail(CommandError::NotOnVariant, P::NoSpindleAddress, c,
                        std::string(info.displayName));
        if (!allowedOnAddress7(c.op))
            return fail(CommandError::BadAddress, P::NotOnAddress7, c);
        return {};
    }
    if (c.op == Op::SpindleSpeed)
        return fail(CommandError::BadAddress, P::SpindleOnAddress7, c);
    // Several GVE114 units may share one line, each on its own address; the others have 0.
    if (c.address != 0 && info.variant != Variant::Gve114)
        return fail(CommandError::BadAddress, P::AddressZeroOnly, c, std::string(info.displayName));
    return {};
}

CommandCheck checkComponents(const Command &c, const VariantInfo &info, std::int64_t lo,
                             std::int64_t hi)
{
    // Adopted reading (§4): 3 components everywhere, the 4th (A) only on 4-axis units.
    if (c.argCount < 3 || c.argCount > info.axisCount) {
        CommandCheck check =
            fail(CommandError::AxisCount, P::ComponentCount, c, std::string(info.displayName));
        check.value = c.argCount;
        check.low = 3;
        check.high = info.axisCount;
        check.message = commandProblemText(check);
        return check;
    }
    for (int i = 0; i < c.argCount; ++i) {
        if (auto r = range(c, c.args[i], lo, hi, "component"))
            return r;
    }
    return {};
}

CommandCheck checkAxis(const Command &c, const VariantInfo &info)
{
    if (static_cast<int>(c.axis) >= info.axisCount)
        return fail(CommandError::NotOnVariant, P::NoSuchAxis, c, std::string(info.displayName),
                    std::string(1, axisLetter(c.axis)));
    return {};
}

CommandCheck needs(bool has, const Command &c, const VariantInfo &info)
{
    if (has)
        return {};
    return fail(CommandError::NotOnVariant, P::NoSuchCommand, c, std::string(info.displayName),
                std::string(mnemonic(c.op)));
}

CommandCheck checkEeprom(const Command &c, const VariantInfo &info)
{
    const bool wide = c.op == Op::EepromReadFloat || c.op == Op::EepromReadUint ||
                      c.op == Op::EepromWriteFloat || c.op == Op::EepromWriteUint;
    if (auto r = needs(!wide || info.hasEepromFloat, c, info))
        return r;
    if (auto r = range(c, c.args[0], 0, 0xFF, "EEPROM address"))
        return r;
    if (c.op == Op::EepromWriteByte)
        return range(c, c.args[1], 0, 0xFF, "byte");
    if (c.op == Op::EepromWriteUint)
        return range(c, c.args[1], 0, kUint32Max, "value");
    if (c.op == Op::EepromWriteFloat && !std::isfinite(c.real))
        return fail(CommandError::OutOfRange, P::NotFinite, c);
    return {};
}

CommandCheck checkHome(const Command &c, const VariantInfo &info, std::int64_t maxRate)
{
    if (auto r = checkAxis(c, info))
        return r;
    if (c.args[0] == 0)
        return fail(CommandError::OutOfRange, P::ZeroTravel, c);
    if (auto r = range(c, c.args[0], -kStepsMax, kStepsMax, "travel"))
        return r;
    if (auto r = range(c, c.args[1], 10, maxRate, "speed toward the switch"))
        return r;
    if (auto r = range(c, c.args[2], 0, kStepsMax, "back-off travel"))
        return r;
    return range(c, c.args[3], 10, maxRate, "speed off the switch");
}

// One case per command of §3-§13, each a line or two: longer than ~60 lines as a table is, and
// clearer whole than split by an arbitrary group of commands.
CommandCheck checkArgs(const Command &c, const VariantInfo &info, std::int64_t maxRate)
{
    const bool fourAxes = info.axisCount == 4;
    switch (c.op) {
    case Op::Line:
    case Op::Vector:
        return checkComponents(c, info, -kStepsMax, kStepsMax);
    case Op::VelocityLimit:
        if (auto r = needs(info.hasVlVkXmNa, c, info))
            return r;
        return checkComponents(c, info, 10, maxRate);
    case Op::Pause:
        return range(c, c.args[0], 1, 24, "pause (ms)");
    case Op::ShortThreshold: // GVE64 documents up to 2^32 - 1, the others 2^31 - 1
        return range(c, c.args[0], 1,
                     info.variant == Variant::Gve64 || info.variant == Variant::Gve64Phantom
                         ? kUint32Max
                         : kStepsMax,
                     "SHORT threshold");
    case Op::Accel: // thousands of pulses/s^2; the manuals give no upper bound
        return range(c, c.args[0], 1, kStepsMax, "acceleration");
    case Op::Speed:
        return range(c, c.args[0], 10, maxRate, "speed");
    case Op::Brake:
        return range(c, c.args[0], 10, maxRate, "brake speed");
    case Op::SpeedModeVk:
    case Op::SpeedModeVn:
        return needs(info.hasVlVkXmNa, c, info);
    case Op::Multiplier: // percent; the manuals give no upper bound
        if (auto r = needs(info.hasVlVkXmNa, c, info))
            return r;
        return range(c, c.args[0], 1, kStepsMax, "multiplier (%)");
    case Op::PositionXYZA:
        return needs(fourAxes, c, info);
    case Op::SetCounter:
        if (auto r = needs(info.hasVlVkXmNa, c, info))
            return r;
        if (auto r = checkAxis(c, info))
            return r;
        return range(c, c.args[0], -kStepsMax, kStepsMax, "counter");
    case Op::Home:
        return checkHome(c, info, maxRate);
    case Op::MpgReporting:
    case Op::MpgSilent:
    case Op::MpgOff:
        return needs(info.hasMpg, c, info);
    case Op::EepromReadByte:
    case Op::EepromWriteByte:
    case Op::EepromReadFloat:
    case Op::EepromReadUint:
    case Op::EepromWriteFloat:
    case Op::EepromWriteUint:
        return checkEeprom(c, info);
    case Op::Output:
        return range(c, c.args[0], 0, 0xFF, "output byte");
    case Op::Input2:
        return needs(info.variant != Variant::Gve84, c, info);
    case Op::StatusRead:
        return range(c, c.args[0], 0, 6, "status number");
    case Op::StatusWrite:
        if (auto r = range(c, c.args[0], 0, 6, "status number"))
            return r;
        return range(c, c.args[1], 0, 0xFF, "status byte");
    case Op::PacketEnd:
        return range(c, c.args[0], 1, kStepsMax, "packet command count");
    case Op::SpindleSpeed:
        return range(c, c.args[0], 0, 1000, "spindle (per mille)");
    default:
        return {};
    }
}

} // namespace

std::string commandProblemText(const CommandCheck &k)
{
    const std::string at = "'" + k.command + "': ";
    switch (k.problem) {
    case P::None:
        return {};
    case P::AddressRange:
        return at + "address must be 0..7";
    case P::NoSpindleAddress:
        return at + k.unit + " has no address 7 (spindle)";
    case P::NotOnAddress7:
        return at + "not a command of address 7";
    case P::SpindleOnAddress7:
        return at + "the spindle speed goes to address 7";
    case P::AddressZeroOnly:
        return at + k.unit + " answers on address 0 only";
    case P::ComponentCount:
        return at + std::to_string(k.value) + " components, " + k.unit + " takes 3" +
               (k.high == 4 ? " or 4" : "");
    case P::ValueOutOfRange:
        return at + k.what + " " + std::to_string(k.value) + " is outside " +
               std::to_string(k.low) + ".." + std::to_string(k.high);
    case P::NotFinite:
        return at + "value is not a finite number";
    case P::ZeroTravel:
        return at + "travel toward the switch must not be 0";
    case P::NoSuchAxis:
        return at + k.unit + " has no axis " + k.what;
    case P::NoSuchCommand:
        return at + k.unit + " has no command " + k.what;
    case P::NotInPacket:
        return at + "only C and B belong in a packet";
    case P::EmptyPacket:
        return "a packet needs at least one command";
    }
    return {};
}

CommandCheck validate(const Command &c, Variant variant, int maxPulseRate)
{
    const VariantInfo &info = variantInfo(variant);
    const std::int64_t maxRate = maxPulseRate > 0 ? maxPulseRate : info.maxPulseRates.back();
    if (auto r = checkAddress(c, info))
        return r;
    return checkArgs(c, info, maxRate);
}

CommandCheck validatePacket(std::span<const Command> commands, Variant variant, int maxPulseRate)
{
    if (commands.empty()) {
        CommandCheck check;
        check.error = CommandError::EmptyPacket;
        check.problem = P::EmptyPacket;
        check.message = commandProblemText(check);
        return check;
    }
    for (const Command &c : commands) {
        if (!allowedInPacket(c.op))
            return fail(CommandError::NotInPacket, P::NotInPacket, c);
        if (auto r = validate(c, variant, maxPulseRate))
            return r;
    }
    return {};
}

} // namespace frezka::protocol
