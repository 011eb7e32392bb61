#include "driver/grinder/wiremodel.h"

#include <algorithm>

namespace frezka::grinder {

void WireModel::setBaud(int baud)
{
    m_byteUs = 10'000'000 / std::max(1, baud > 0 ? baud : 9600);
}

void WireModel::reset(std::int64_t nowUs)
{
    m_endUs = nowUs;
    m_accepted = 0;
}

void WireModel::accepted(std::int64_t nowUs, std::int64_t bytes)
{
    if (bytes <= 0)
        return;
    m_endUs = std::max(nowUs, m_endUs) + bytes * m_byteUs;
    m_accepted += bytes;
}

std::int64_t WireModel::sentBy(std::int64_t nowUs) const
{
    if (nowUs >= m_endUs)
        return m_accepted;
    // Bytes still to leave: the time left, rounded up to whole bytes.
    const std::int64_t onWire = (m_endUs - nowUs + m_byteUs - 1) / m_byteUs;
    return std::max<std::int64_t>(0, m_accepted - onWire);
}

namespace {

// Line level at `bit` (in sender bit times): start 0, data LSB first, stop 1, idle 1 after.
int lineLevel(const std::vector<std::uint8_t> &bytes, std::int64_t bit)
{
    if (bit < 0 || bit >= std::int64_t(bytes.size()) * 10)
        return 1;
    const std::int64_t pos = bit % 10;
    if (pos == 0)
        return 0;
    if (pos == 9)
        return 1;
    return (bytes[std::size_t(bit / 10)] >> (pos - 1)) & 1;
}

} // namespace

std::vector<std::uint8_t> resampleUart(const std::vector<std::uint8_t> &bytes, int senderBaud,
                                       int receiverBaud)
{
    if (senderBaud == receiverBaud || senderBaud <= 0 || receiverBaud <= 0)
        return bytes;
    // Times in seconds; the sender's bit k spans [k / senderBaud, (k + 1) / senderBaud).
    const double senderBit = 1.0 / senderBaud;
    const double receiverBit = 1.0 / receiverBaud;
    const double end = double(bytes.size()) * 10 * senderBit;
    const auto level = [&](double t) { return lineLevel(bytes, std::int64_t(t / senderBit)); };
    std::vector<std::uint8_t> out;
    double t = 0;
    while (t < end) {
        // The next start bit: the first sender bit at or after t that is low.
        std::int64_t k = std::int64_t(t / senderBit);
        while (k * senderBit < end && lineLevel(bytes, k) != 0)
            ++k;
        if (k * senderBit >= end)
            break;
        const double start = std::max(t, k * senderBit);
        std::uint8_t value = 0;
        for (int j = 0; j < 8; ++j)
            value |= std::uint8_t(level(start + (j + 1.5) * receiverBit) << j);
        const double stop = start + 9.5 * receiverBit;
        out.push_back(level(stop) ? value : 0x00);
        t = stop;
    }
    return out;
}

} // namespace frezka::grinder
