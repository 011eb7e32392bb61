#include "variant.h"

#include <array>

namespace frezka::protocol {
namespace {

constexpr std::array<int, 3> kRates84{15000, 50000, 100000};
constexpr std::array<int, 2> kRates64{50000, 125000};
constexpr std::array<int, 1> kRatesPhantom{200000};
constexpr std::array<int, 4> kRates114{50000, 125000, 200000, 500000};
constexpr std::array<int, 2> kBauds84{38400, 115200};
constexpr std::array<int, 4> kBauds64{19200, 38400, 57600, 115200};
constexpr std::array<int, 7> kBauds114{19200, 38400, 57600, 115200, 230400, 460800, 921600};

const std::array<VariantInfo, 4> kVariants{{
    {Variant::Gve84, "gve84", "GVE84", 3, kRates84, 50000, 64, kBauds84, 115200, false, false,
     false, true, 1, 35000, "IP84 v3 27.1.2010", "27011001"},
    {Variant::Gve64, "gve64", "GVE64", 4, kRates64, 50000, 420, kBauds64, 115200, true, true, true,
     true, 4, 35000, "IP64MPG v19 10.9.2010", "25020304"},
    {Variant::Gve64Phantom, "gve64-phantom", "GVE64 PHANTOM", 4, kRatesPhantom, 200000, 420,
     kBauds64, 115200, true, true, true, true, 4, 35000, "IP64MPG v19 10.9.2010", "25020305"},
    {Variant::Gve114, "gve114", "GVE114", 4, kRates114, 125000, 2048, kBauds114, 115200, true, true,
     true, true, 4, 50000, "IP114/500 x16 16.9.2018", "16091801"},
}};

} // namespace

const VariantInfo &variantInfo(Variant v)
{
    return kVariants[static_cast<std::size_t>(v)];
}

std::span<const VariantInfo> allVariants()
{
    return kVariants;
}

std::optional<Variant> variantFromId(std::string_view id)
{
    for (const auto &info : kVariants) {
        if (info.id == id)
            return info.variant;
    }
    return std::nullopt;
}

std::optional<Variant> variantFromFirmware(std::string_view firmware)
{
    // PHANTOM reports the GVE64 firmware string; the profile tells them apart.
    if (firmware.starts_with("IP84"))
        return Variant::Gve84;
    if (firmware.starts_with("IP64"))
        return Variant::Gve64;
    if (firmware.starts_with("IP114"))
        return Variant::Gve114;
    return std::nullopt;
}

std::optional<int> firmwareVersion(std::string_view firmware)
{
    const auto at = firmware.find(" v");
    if (at == std::string_view::npos)
        return std::nullopt;
    int version = 0, digits = 0;
    for (std::size_t i = at + 2; i < firmware.size() && digits < 4; ++i, ++digits) {
        const char c = firmware[i];
        if (c < '0' || c > '9')
            break;
        version = version * 10 + (c - '0');
    }
    return digits > 0 ? std::optional<int>(version) : std::nullopt;
}

Features featuresOf(Variant v, std::optional<int> version)
{
    const VariantInfo &info = variantInfo(v);
    Features f{info.hasMpg, info.hasEepromFloat, info.hasVlVkXmNa, true};
    if ((v == Variant::Gve64 || v == Variant::Gve64Phantom) && version) {
        f.switchHoming = *version >= 10;
        f.mpg = f.mpg && *version >= 10;
        f.eepromFloat = f.eepromFloat && *version >= 10;
        f.vlVkXmNa = f.vlVkXmNa && *version >= 19;
    }
    return f;
}

} // namespace frezka::protocol
