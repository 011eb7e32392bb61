// The EEPROM, status, input/output and MPG commands of the emulated unit
// (docs/gve-protocol.md §10, §12, §13).

#include "driver/emulator/commandargs.h"
#include "driver/emulator/unit_impl.h"

#include <charconv>
#include <cmath>

namespace frezka::emulator {

using namespace args;

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
    settingsChanged(); // the unit acts on what it holds now (unitsettings.h)
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
    noteSpindle();
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
