#pragma once
// Capability table of the GVE interpolator variants (docs/gve-protocol.md §1, §3, §11).
// One place for every per-variant fact the codec, the emulator, the driver and the GUI need.

#include <optional>
#include <span>
#include <string_view>

namespace frezka::protocol {

enum class Variant { Gve84, Gve64, Gve64Phantom, Gve114 };

struct VariantInfo
{
    Variant variant;
    std::string_view id;                // command-line / profile name: "gve84", "gve64", ...
    std::string_view displayName;       // "GVE64 PHANTOM"
    int axisCount;                      // interpolated axes: 3 (XYZ) or 4 (XYZA)
    std::span<const int> maxPulseRates; // orderable maximum pulse rates, pulses/s
    int defaultMaxPulseRate;            // pulses/s of the default (emulated) unit
    int queueCapacity;                  // C vectors: one executing plus the rest waiting
    std::span<const int> bauds;         // selectable baud rates
    int defaultBaud;
    bool hasSpindleAddress7;    // address 7 answers (§9)
    bool hasMpg;                // Y+/Y&/Y- (§13)
    bool hasEepromFloat;        // EFR/EUR/EFW/EUW (§12)
    bool hasVlVkXmNa;           // VL, VK, XM, N<axis> (§4, §5)
    int relayOutputs;           // 1 on GVE84, 4 on GVE64/GVE114
    int resetBrakeSpeed;        // B after reset, pulses/s
    std::string_view firmware;  // reply to '?', without the "0,"
    std::string_view defaultId; // reply to 'Q' (ddmmyypp) of the emulated unit
};

// The table entry of a variant; never fails.
const VariantInfo &variantInfo(Variant v);
// All variants in table order.
std::span<const VariantInfo> allVariants();
// Look up by id ("gve84", "gve64", "gve64-phantom", "gve114"); nullopt when unknown.
std::optional<Variant> variantFromId(std::string_view id);
// Guess the variant from a '?' firmware string ("IP84 v3 ...", "IP64MPG v19 ...", "IP114/500 ...").
std::optional<Variant> variantFromFirmware(std::string_view firmware);

// The version number in a '?' firmware string: the digits after the first " v" ("IP64MPG v19
// 10.9.2010" -> 19); nullopt when there is none (the GVE114 prints none).
std::optional<int> firmwareVersion(std::string_view firmware);

// What a unit can do, by its variant and firmware version (§1): the GVE64 (and PHANTOM, which
// reports the GVE64 firmware) gained the MPG and the EEPROM float/uint32 commands in v10 and
// VL, VK, XM and N<axis> in v19. An unknown version counts as the variant's full set.
struct Features
{
    bool mpg = false;
    bool eepromFloat = false;
    bool vlVkXmNa = false;
    bool switchHoming = true; // W: GVE64 from IP64MPG v10 (manual §14.1)
    friend bool operator==(const Features &, const Features &) = default;
};
Features featuresOf(Variant v, std::optional<int> version);

} // namespace frezka::protocol
