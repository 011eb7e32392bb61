#include "readings.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>

namespace frezka::emulator::readings {

ReplyParts packetReply(int code, int acceptedCount)
{
    return {code, std::to_string(acceptedCount)};
}

int vectorComponentCountCode(int count, int axisCount)
{
    if (count < 3 || count > 4)
        return 4;
    if (count == 4 && axisCount < 4)
        return 4;
    return 0;
}

bool advancesIndex(std::string_view mnemonic)
{
    return !(mnemonic.starts_with('@') || mnemonic.starts_with('>'));
}

std::string formatEepromFloat(float value)
{
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, res.ptr);
}

ReplyParts mpgReply(int code, std::string_view echoedCommand)
{
    return {code, std::string(echoedCommand)};
}

std::int64_t shortnessMeasure(const std::array<std::int64_t, 4> &steps)
{
    std::int64_t major = 0;
    for (auto s : steps)
        major = std::max(major, s < 0 ? -s : s);
    return major;
}

double cruiseSpeed(bool isShort, double v, double b)
{
    return isShort ? std::min(v, b) : v;
}

double multipliedSpeed(double v, int xmPercent, double vlCapForVector)
{
    const double boosted = v * xmPercent / 100.0;
    if (xmPercent <= 100)
        return boosted;
    return std::max(v, std::min(boosted, vlCapForVector));
}

} // namespace frezka::emulator::readings
