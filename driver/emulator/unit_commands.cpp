// The command set of the emulated unit (docs/gve-protocol.md §4-§13): each handler validates
// all parameters first (syntax -> 4, range -> 5), then changes state.

#include "driver/emulator/commandargs.h"
#include "driver/emulator/unit_impl.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace frezka::emulator {

using namespace args;

namespace {

constexpr std::int64_t kMaxSteps = 2147483647;
constexpr Reply kDeferred{-1, {}};

} // namespace

// Identification and link commands, the same on addresses 0 and 7; nullopt for the others.
std::optional<Reply> Unit::Impl::executeLink(std::string_view body)
{
    if (body == "?")
        return Reply{0, firmware};
    if (body == "Q")
        return Reply{0, std::string(info->defaultId)};
    if (body == "@")
        return Reply{0, std::to_string(index)};
    if (body == ">") {
        if (lastReply.empty())
            return Reply{0, {}};
        tx += lastReply; // the same bytes again, not executed again
        return kDeferred;
    }
    if (body == "J") {
        sendReply({0, {}}); // answered before the reset
        resetState(false);
        deafUntil = engine.now() + readings::kResetSeconds;
        return kDeferred;
    }
    if (body == "%+" || body == "%-") {
        checksums = body == "%+";
        return Reply{0, {}};
    }
    return std::nullopt;
}

// One command of the unit: link commands, packets, what older firmware lacks, then one case per
// command letter; a dispatch table, kept whole (over 60 lines) so that every command is found here.
Reply Unit::Impl::execute(int address, std::string_view body)
{
    if (address == 7 && address != options.address)
        return executeSpindle(body);
    if (body.empty())
        return {3, {}};
    if (auto link = executeLink(body))
        return *link;
    if (body == "*S") {
        packetOpen = true;
        packet.clear();
        packetLastLine = engine.now();
        return kDeferred; // a packet is answered once, at its end
    }
    if (body.starts_with("*E"))
        return {4, {}}; // end of a packet that was never started
    const char c = body.front();
    const std::string_view rest = body.substr(1);
    // What an older firmware does not know yet (§1): unknown command.
    const bool v19 = body.starts_with("VL") || body.starts_with("VK") || body.starts_with("VN") ||
                     body.starts_with("XM") || (c == 'N' && !rest.empty());
    const bool v10 = c == 'Y' || body.starts_with("EF") || body.starts_with("EU");
    if ((v19 && !features.vlVkXmNa) || (v10 && !(c == 'Y' ? features.mpg : features.eepromFloat)))
        return {3, {}};
    switch (c) {
    case 'L':
    case 'C':
        return cmdVector(c, rest);
    case 'T':
    case '$':
    case 'A':
    case 'B':
    case 'V':
        return cmdSpeeds(body.substr(0, 1), rest);
    case 'X':
        return cmdExchange(rest);
    case 'P':
        return cmdPosition(rest);
    case 'N':
        return cmdNull(rest);
    case 'W':
        return cmdHoming(rest);
    case 'K':
    case 'R':
    case 'H':
    case 'G':
    case 'D':
        if (!rest.empty())
            return {4, {}};
        return cmdQueue(c);
    case 'E':
        return cmdEeprom(rest);
    case 'S':
    case 'F':
        return cmdStatus(body);
    case 'O':
    case 'I':
        return cmdIo(body);
    case 'Y':
        return cmdMpg(rest);
    default:
        return {3, {}};
    }
}

// docs/gve-protocol.md §9: address 7 of GVE64/114 (spindle) plus the shared commands.
Reply Unit::Impl::executeSpindle(std::string_view body)
{
    if (auto link = executeLink(body))
        return *link;
    if (body.starts_with("E"))
        return cmdEeprom(body.substr(1));
    if (!body.starts_with("V") || body.starts_with("VL") || body.starts_with("VK") ||
        body.starts_with("VN"))
        return {3, {}};
    std::vector<std::int64_t> v;
    const auto parts = split(body.substr(1));
    if (parts.size() != 1)
        return {4, {}};
    if (const int code = parseAll(parts, 0, 1000, v))
        return {code, {}};
    spindle = static_cast<int>(v[0]);
    outputs = spindle == 0 ? (outputs | 0x01) : (outputs & ~0x01); // OUT0 follows (active low)
    noteSpindle();
    return {0, {}};
}

// docs/gve-protocol.md §2.2 with the adopted reading on partial failure.
Reply Unit::Impl::executePacket(int declaredCount)
{
    if (declaredCount != static_cast<int>(packet.size()))
        return readings::packetReply(4, 0); // a line went missing: run none of them
    int accepted = 0;
    for (const PacketLine &pl : packet) {
        int code = pl.failCode;
        if (code == 0) {
            const std::string_view b = pl.body;
            if (b.starts_with("C"))
                code = cmdVector('C', b.substr(1)).code;
            else if (b.starts_with("B"))
                code = cmdSpeeds("B", b.substr(1)).code;
            else
                code = readings::kForeignCommandInPacketCode;
        }
        if (code != 0)
            return readings::packetReply(code, accepted);
        ++accepted;
    }
    return readings::packetReply(0, accepted);
}

// §4: L and C vectors.
Reply Unit::Impl::cmdVector(char kind, std::string_view args)
{
    const auto parts = split(args);
    if (const int code =
            readings::vectorComponentCountCode(static_cast<int>(parts.size()), info->axisCount))
        return {code, {}};
    std::vector<std::int64_t> v;
    if (const int code = parseAll(parts, -kMaxSteps, kMaxSteps, v))
        return {code, {}};
    if (mpg != Mpg::Off)
        return {readings::kMpgRefusalCode, {}};
    if (homing)
        return {1, {}};
    if (kind == 'L') {
        if (!engine.isIdle())
            return {1, {}}; // §4: L only when the queue is empty
    } else {
        if (kept)
            return {readings::kContinuousWhileKeptCode, {}};
        if (engine.queueLength() >= static_cast<std::size_t>(info->queueCapacity))
            return {1, {}};
    }
    MotionVector mv;
    for (std::size_t i = 0; i < v.size(); ++i)
        mv.steps[i] = v[i];
    mv.isLine = kind == 'L';
    mv.isShort = readings::shortnessMeasure(mv.steps) < shortSteps;
    mv.velocityCorrection = velocityCorrection;
    mv.speedPulsesPerS = speed;
    mv.brakePulsesPerS = brake;
    mv.accelPulsesPerS2 = accelK * 1000.0;
    mv.serial = ++serial;
    engine.enqueue(mv);
    return {0, {}};
}

// §4: T, $, A, V, B and VL/VK/VN.
Reply Unit::Impl::cmdSpeeds(std::string_view mnemonic, std::string_view args)
{
    std::vector<std::int64_t> v;
    if (mnemonic == "V" && (args == "K" || args == "N")) {
        velocityCorrection = args == "K";
        return {0, {}};
    }
    if (mnemonic == "V" && args.starts_with("L")) {
        const auto parts = split(args.substr(1));
        if (const int code =
                readings::vectorComponentCountCode(static_cast<int>(parts.size()), info->axisCount))
            return {code, {}};
        if (const int code = parseAll(parts, 10, maxRate, v))
            return {code, {}};
        for (std::size_t i = 0; i < v.size(); ++i)
            limits.velocityLimitPulsesPerS[i] = v[i] * readings::kVelocityLimitUnitPulsesPerS;
        engine.setLimits(limits);
        return {0, {}};
    }
    const auto parts = split(args);
    if (parts.size() != 1)
        return {4, {}};
    const char m = mnemonic.front();
    // Ranges as the manuals give them (docs/emulator.md "Parameter ranges"): T 1..24 ms; $ up
    // to 2^32 - 1 on the GVE64 (its manual), 2^31 - 1 on the GVE84 and GVE114; V and B 10..the
    // unit's pulse rate; A has no documented bound (readings::kAccelMaxK).
    const bool wideShort = options.variant == protocol::Variant::Gve64 ||
                           options.variant == protocol::Variant::Gve64Phantom;
    const std::int64_t shortMax = wideShort ? 4294967295LL : kMaxSteps;
    const std::int64_t lo = m == 'T' || m == 'A' || m == '$' ? 1 : 10;
    const std::int64_t hi = m == 'T'   ? 24
                            : m == 'A' ? readings::kAccelMaxK
                            : m == '$' ? shortMax
                                       : maxRate;
    if (const int code = parseAll(parts, lo, hi, v))
        return {code, {}};
    switch (m) {
    case 'T':
        pauseMs = static_cast<int>(v[0]);
        engine.setPauseS(pauseMs / 1000.0);
        break;
    case '$':
        shortSteps = v[0];
        break;
    case 'A':
        accelK = static_cast<int>(v[0]);
        break;
    case 'V':
        speed = static_cast<int>(v[0]);
        break;
    default:
        brake = static_cast<int>(v[0]);
        break;
    }
    return {0, {}};
}

// §4.1: XA, XU, XD, XMn.
Reply Unit::Impl::cmdExchange(std::string_view args)
{
    if (args.starts_with("M")) {
        std::vector<std::int64_t> v;
        const auto parts = split(args.substr(1));
        if (parts.size() != 1)
            return {4, {}};
        if (const int code = parseAll(parts, 1, readings::kMultiplierMaxPercent, v))
            return {code, {}};
        limits.xmPercent = static_cast<int>(v[0]);
        engine.setLimits(limits);
        return {0, {}};
    }
    if (args != "A" && args != "U" && args != "D")
        return {3, {}};
    for (MotionVector &mv : engine.queue()) {
        if (mv.isHoming)
            continue;
        if (args == "A") {
            mv.speedPulsesPerS = speed;
            if (options.variant != protocol::Variant::Gve84)
                mv.accelPulsesPerS2 = accelK * 1000.0; // GVE64/114: also the acceleration
        } else {
            const double delta = mv.speedPulsesPerS / 16.0;
            mv.speedPulsesPerS = std::clamp(mv.speedPulsesPerS + (args == "U" ? delta : -delta),
                                            10.0, double(maxRate));
        }
    }
    return {0, {}};
}

// §5: P, PF, P4.
Reply Unit::Impl::cmdPosition(std::string_view rest)
{
    const auto pos = counters();
    int count = 0;
    if (rest.empty())
        count = 2;
    else if (rest == "F")
        count = 3;
    else if (rest == "4" && hasFourAxes())
        count = 4;
    else
        return {3, {}};
    std::string values;
    for (int i = 0; i < count; ++i)
        values += (i ? "," : "") + std::to_string(pos[i]);
    return {0, values};
}

// §5: N and N<axis><n>.
Reply Unit::Impl::cmdNull(std::string_view args)
{
    if (args.empty()) {
        if (runBit())
            return {7, {}};
        for (int i = 0; i < 4; ++i)
            engine.setPosition(i, 0);
        checkInterrupts();
        return {0, {}};
    }
    const int axis = axisIndex(args.front(), info->axisCount);
    if (axis < 0)
        return {4, {}};
    std::vector<std::int64_t> v;
    const auto parts = split(args.substr(1));
    if (parts.size() != 1)
        return {4, {}};
    if (const int code = parseAll(parts, -kMaxSteps, kMaxSteps, v))
        return {code, {}};
    if (runBit())
        return {7, {}};
    engine.setPosition(axis, v[0]);
    checkInterrupts();
    return {0, {}};
}

// §6: Wa,n2,n3,n4,n5 (also without the comma after the axis). Replies when homing ends.
Reply Unit::Impl::cmdHoming(std::string_view args)
{
    if (args.empty())
        return {4, {}};
    const int axis = axisIndex(args.front(), info->axisCount);
    if (axis < 0)
        return {4, {}};
    std::string_view rest = args.substr(1);
    if (rest.starts_with(","))
        rest.remove_prefix(1);
    const auto parts = split(rest);
    if (parts.size() != 4)
        return {4, {}};
    std::vector<std::int64_t> v;
    if (const int code = parseAll(parts, -kMaxSteps, kMaxSteps, v))
        return {code, {}};
    if (v[0] == 0 || v[1] < 10 || v[1] > maxRate || v[2] < 0 || v[3] < 10 || v[3] > maxRate)
        return {5, {}};
    if (runBit() || inta)
        return {7, {}};
    homing = Homing{
        axis, v[0], v[0] > 0 ? -v[2] : v[2], static_cast<int>(v[1]), static_cast<int>(v[3]), false};
    deferred = Deferred::Homing;
    if (!homeSwitchPressed()) {
        MotionVector mv;
        mv.isHoming = true;
        mv.steps[axis] = v[0];
        mv.speedPulsesPerS = static_cast<double>(v[1]);
        engine.enqueue(mv);
    }
    checkHoming(); // already on the switch: back off at once
    return kDeferred;
}

// §7: K, R, H, G, D.
Reply Unit::Impl::cmdQueue(char c)
{
    const bool moving = engine.isRunning() || homing.has_value();
    switch (c) {
    case 'H':
        intcom = true;
        inta = true;
        stopBit = engine.isMoving();
        deferred = Deferred::Halt;
        engine.requestStop(); // replies from onStopped(), at once when nothing moves
        return kDeferred;
    case 'G':
        if (!inta)
            return {6, {}};
        inta = intcom = false;
        st[4] = st[5] = 0;
        engine.release();
        return {engine.isIdle() ? readings::kGoNothingLeftCode : 0, {}};
    case 'D':
        if (moving)
            return {7, {}};
        engine.clear();
        st[4] = st[5] = 0;
        inta = intcom = stopBit = freeBit = false;
        engine.release();
        return {0, {}};
    case 'K':
        if (moving || kept)
            return {moving ? 7 : readings::kKeepRestoreMisuseCode, {}};
        keptQueue = engine.takeQueue();
        keptSt[0] = st[4];
        keptSt[1] = st[5];
        keptInta = inta;
        keptIntcom = intcom;
        st[4] = st[5] = 0;
        inta = intcom = stopBit = false;
        engine.release();
        kept = true;
        return {0, {}};
    default: // 'R'
        if (moving || !kept)
            return {moving ? 7 : readings::kKeepRestoreMisuseCode, {}};
        engine.restoreQueue(std::move(keptQueue));
        keptQueue = {};
        st[4] = keptSt[0];
        st[5] = keptSt[1];
        inta = keptInta;
        intcom = keptIntcom;
        kept = false;
        if (inta)
            engine.requestStop(); // held again until G
        return {0, {}};
    }
}

} // namespace frezka::emulator
