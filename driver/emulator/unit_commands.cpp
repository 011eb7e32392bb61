// The command set of the emulated unit (docs/gve-protocol.md §4-§13): each handler validates
// all parameters first (syntax -> 4, range -> 5), then changes state.

#include "driver/emulator/unit_impl.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace frezka::emulator {
namespace {

constexpr std::int64_t kMaxSteps = 2147483647;
constexpr Reply kDeferred{-1, {}};

enum class Num { Ok, Syntax, Range };

struct Parsed
{
    Num status = Num::Syntax;
    std::int64_t value = 0;
};

// Decimal integer with optional sign; more digits than int64 holds is a range error.
Parsed parseDec(std::string_view s)
{
    if (!s.empty() && s.front() == '+')
        s.remove_prefix(1);
    if (s.empty())
        return {};
    bool neg = false;
    std::string_view digits = s;
    if (digits.front() == '-') {
        neg = true;
        digits.remove_prefix(1);
    }
    if (digits.empty())
        return {};
    for (char c : digits) {
        if (c < '0' || c > '9')
            return {};
    }
    std::int64_t v = 0;
    const auto res = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (res.ec == std::errc::result_out_of_range)
        return {Num::Range, 0};
    return {Num::Ok, neg ? -v : v};
}

// Hex number of 1..8 digits.
Parsed parseHex(std::string_view s)
{
    if (s.empty() || s.size() > 8)
        return {s.empty() ? Num::Syntax : Num::Range, 0};
    std::uint64_t v = 0;
    const auto res = std::from_chars(s.data(), s.data() + s.size(), v, 16);
    if (res.ec != std::errc() || res.ptr != s.data() + s.size())
        return {};
    return {Num::Ok, static_cast<std::int64_t>(v)};
}

std::vector<std::string_view> split(std::string_view s)
{
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (;;) {
        const auto comma = s.find(',', start);
        parts.push_back(s.substr(start, comma - start));
        if (comma == std::string_view::npos)
            return parts;
        start = comma + 1;
    }
}

// Parses every value, then checks ranges: a syntax error anywhere wins over a range error.
int parseAll(const std::vector<std::string_view> &parts, std::int64_t lo, std::int64_t hi,
             std::vector<std::int64_t> &out, bool hex = false)
{
    int code = 0;
    out.clear();
    for (auto p : parts) {
        const Parsed v = hex ? parseHex(p) : parseDec(p);
        if (v.status == Num::Syntax)
            return 4;
        if (v.status == Num::Range || v.value < lo || v.value > hi)
            code = 5;
        out.push_back(v.value);
    }
    return code;
}

std::string hex2(int v)
{
    static constexpr char kHex[] = "0123456789ABCDEF";
    return {kHex[(v >> 4) & 0xF], kHex[v & 0xF]};
}

int axisIndex(char c, int axisCount)
{
    static constexpr std::string_view kAxes = "XYZA";
    const auto i = kAxes.find(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    if (i == std::string_view::npos || static_cast<int>(i) >= axisCount)
        return -1;
    return static_cast<int>(i);
}

} // namespace

Reply Unit::Impl::execute(int address, std::string_view body)
{
    if (address == 7 && address != options.address)
        return executeSpindle(body);
    if (body.empty())
        return {3, {}};
    if (body == "?")
        return {0, std::string(info->firmware)};
    if (body == "Q")
        return {0, std::string(info->defaultId)};
    if (body == "@")
        return {0, std::to_string(index)};
    if (body == ">") {
        if (lastReply.empty())
            return {0, {}};
        tx += lastReply;
        return kDeferred;
    }
    if (body == "J") {
        sendReply({0, {}});
        resetState(false);
        deafUntil = engine.now() + readings::kResetSeconds;
        return kDeferred;
    }
    if (body == "%+" || body == "%-") {
        checksums = body == "%+";
        return {0, {}};
    }
    if (body == "*S") {
        packetOpen = true;
        packet.clear();
        packetLastLine = engine.now();
        return kDeferred;
    }
    if (body.starts_with("*E"))
        return {4, {}}; // end of a packet that was never started
    const char c = body.front();
    const std::string_view rest = body.substr(1);
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
    if (body == "?" || body == "Q" || body == "@" || body == ">" || body == "J" || body == "%+" ||
        body == "%-" || body.starts_with("E"))
        return execute(options.address, body);
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
    const std::int64_t shortMax =
        options.variant == protocol::Variant::Gve84 ? kMaxSteps : 4294967295LL;
    const std::int64_t lo = m == 'T' || m == 'A' || m == '$' ? 1 : 10;
    const std::int64_t hi = m == 'T' ? 24 : m == 'A' ? 100000 : m == '$' ? shortMax : maxRate;
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
        if (const int code = parseAll(parts, 1, 1000, v))
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
    const auto pos = engine.position();
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

// §12: ER/EW on every variant, EFR/EUR/EFW/EUW on GVE64/114.
Reply Unit::Impl::cmdEeprom(std::string_view rest)
{
    std::string_view op;
    for (std::string_view candidate : {"FR", "UR", "FW", "UW", "R", "W"}) {
        if (rest.starts_with(candidate)) {
            op = candidate;
            break;
        }
    }
    if (op.empty() || (op.size() == 2 && !info->hasEepromFloat))
        return {3, {}};
    const auto parts = split(rest.substr(op.size()));
    const bool write = op.back() == 'W';
    if (parts.size() != (write ? 2u : 1u))
        return {4, {}};
    const Parsed addr = parseHex(parts[0]);
    if (addr.status == Num::Syntax)
        return {4, {}};
    const bool wide = op.size() == 2;
    if (addr.status == Num::Range || addr.value > (wide ? 0xFC : 0xFF))
        return {5, {}};
    const int a = static_cast<int>(addr.value);
    if (!write) {
        if (op == "R")
            return {0, hex2(eeprom.byte(a))};
        if (op == "FR")
            return {0, readings::formatEepromFloat(eeprom.readFloat(a))};
        return {0, std::to_string(eeprom.readUint32(a))};
    }
    if (op == "W") {
        const Parsed value = parseHex(parts[1]);
        if (value.status == Num::Syntax)
            return {4, {}};
        if (value.status == Num::Range || value.value > 0xFF)
            return {5, {}};
        eeprom.setByte(a, static_cast<std::uint8_t>(value.value));
    } else if (op == "FW") {
        float f = 0;
        const auto text = parts[1];
        const auto res = std::from_chars(text.data(), text.data() + text.size(), f);
        if (res.ec == std::errc::invalid_argument || res.ptr != text.data() + text.size())
            return {4, {}};
        if (res.ec == std::errc::result_out_of_range || !std::isfinite(f))
            return {5, {}};
        eeprom.writeFloat(a, f);
    } else {
        const Parsed value = parseDec(parts[1]);
        if (value.status == Num::Syntax)
            return {4, {}};
        if (value.status == Num::Range || value.value < 0 || value.value > 0xFFFFFFFFLL)
            return {5, {}};
        eeprom.writeUint32(a, static_cast<std::uint32_t>(value.value));
    }
    if (!options.eepromFile.empty())
        eepromError = eeprom.save(options.eepromFile);
    return {0, {}};
}

// §10: SRn, SWn,hh, F.
Reply Unit::Impl::cmdStatus(std::string_view body)
{
    if (body == "F")
        return {0, hex2(st6() | (engine.queueLength() >= std::size_t(info->queueCapacity) ||
                                         (kept && !engine.isIdle())
                                     ? 0x20
                                     : 0))};
    if (body.size() < 3 || (body[1] != 'R' && body[1] != 'W'))
        return {3, {}};
    const auto parts = split(body.substr(2));
    const bool write = body[1] == 'W';
    if (parts.size() != (write ? 2u : 1u))
        return {4, {}};
    const Parsed n = parseDec(parts[0]);
    if (n.status == Num::Syntax)
        return {4, {}};
    std::int64_t value = 0;
    if (write) {
        const Parsed v = parseHex(parts[1]);
        if (v.status == Num::Syntax)
            return {4, {}};
        if (v.status == Num::Range || v.value > 0xFF)
            return {5, {}};
        value = v.value;
    }
    if (n.status == Num::Range || n.value < 0 || n.value > 6)
        return {5, {}};
    const int idx = static_cast<int>(n.value);
    if (!write)
        return {0, hex2(idx == 6 ? st6() : st[idx])};
    if (idx < 6) {
        st[idx] = static_cast<std::uint8_t>(value);
        checkInterrupts();
        return {0, {}};
    }
    // SW6: STOP, FREE, INTCOM and INTA are writable; RUN follows the queue.
    stopBit = value & 0x01;
    freeBit = value & 0x02;
    intcom = value & 0x10;
    const bool newInta = value & 0x80;
    if (newInta && !inta)
        engine.requestStop();
    else if (!newInta && inta)
        engine.release();
    inta = newInta;
    return {0, {}};
}

// §10: O0,hh; I1; I2.
Reply Unit::Impl::cmdIo(std::string_view body)
{
    const std::uint16_t levels = inputLevels();
    if (body == "I1")
        return {0, hex2(levels & 0xFF)};
    if (body == "I2" && options.variant != protocol::Variant::Gve84)
        return {0, hex2(levels >> 8)};
    if (body.front() == 'I')
        return {3, {}};
    const auto parts = split(body.substr(1));
    if (parts.size() != 2)
        return {4, {}};
    const Parsed port = parseHex(parts[0]);
    const Parsed value = parseHex(parts[1]);
    if (port.status == Num::Syntax || value.status == Num::Syntax)
        return {4, {}};
    if (port.status == Num::Range || port.value != 0 || value.status == Num::Range ||
        value.value > 0xFF)
        return {5, {}};
    outputs = static_cast<std::uint8_t>(value.value);
    return {0, {}};
}

// §13: Y+, Y&, Y-.
Reply Unit::Impl::cmdMpg(std::string_view rest)
{
    if (!info->hasMpg)
        return {3, {}};
    if (rest != "+" && rest != "&" && rest != "-")
        return {4, {}};
    const std::string echo = "Y" + std::string(rest);
    if (rest != "-" && (!engine.isIdle() || homing))
        return readings::mpgReply(7, echo);
    mpg = rest == "+" ? Mpg::Reporting : rest == "&" ? Mpg::Silent : Mpg::Off;
    return readings::mpgReply(0, echo);
}

} // namespace frezka::emulator
