#include "driver/grinder/framedecoder.h"

namespace frezka::grinder {

FrameDecoder::FrameDecoder(Framing framing)
    : m_framing(framing)
{}

std::size_t FrameDecoder::pendingTotal() const
{
    return m_frame.size() >= 4 ? m_total : 0;
}

void FrameDecoder::feed(const std::uint8_t *bytes, std::size_t size,
                        std::vector<DecodeEvent> &events)
{
    for (std::size_t i = 0; i < size; ++i)
        consume(bytes[i], events);
}

void FrameDecoder::reset(std::vector<DecodeEvent> &events)
{
    m_noise.insert(m_noise.end(), m_frame.begin(), m_frame.end());
    m_frame.clear();
    m_total = 0;
    flushNoise(events);
}

void FrameDecoder::flushNoise(std::vector<DecodeEvent> &events)
{
    if (m_noise.empty())
        return;
    DecodeEvent event;
    event.kind = DecodeEvent::Kind::Noise;
    event.noise = std::move(m_noise);
    m_noise.clear();
    events.push_back(std::move(event));
}

void FrameDecoder::consume(std::uint8_t byte, std::vector<DecodeEvent> &events)
{
    if (m_frame.empty()) {
        if (byte == kStartByte)
            m_frame.push_back(byte);
        else
            m_noise.push_back(byte);
        return;
    }
    m_frame.push_back(byte);
    if (m_frame.size() == 2) {
        if (!isKnownCode(m_framing, byte))
            rejectStart(events);
        return;
    }
    if (m_frame.size() == 4) {
        const std::size_t length = (std::size_t(m_frame[2]) << 8) | m_frame[3];
        const Code code = static_cast<Code>(m_frame[1]);
        const bool control = isControlCode(m_framing, code);
        if ((control && length != 0) || (carriesHeader(m_framing, code) && length < kHeaderSize)) {
            rejectStart(events);
            return;
        }
        m_total = 4 + length + checksumSize(m_framing);
        flushNoise(events); // the start is plausible: what came before it was noise
        return;
    }
    if (m_frame.size() > 4 && m_frame.size() == m_total)
        finish(events);
}

void FrameDecoder::rejectStart(std::vector<DecodeEvent> &events)
{
    // The AA was noise; scan the bytes after it again (one of them may be the real start).
    Bytes rest(m_frame.begin() + 1, m_frame.end());
    m_noise.push_back(m_frame.front());
    m_frame.clear();
    m_total = 0;
    for (std::uint8_t byte : rest)
        consume(byte, events);
}

void FrameDecoder::finish(std::vector<DecodeEvent> &events)
{
    const std::size_t sumSize = checksumSize(m_framing);
    const std::size_t body = m_frame.size() - sumSize;
    const std::uint16_t expected = frameChecksum(m_framing, m_frame.data(), body);
    std::uint16_t received = m_frame[body];
    if (sumSize == 2)
        received = static_cast<std::uint16_t>((received << 8) | m_frame[body + 1]);

    DecodeEvent event;
    event.kind = expected == received ? DecodeEvent::Kind::Frame : DecodeEvent::Kind::ChecksumError;
    event.frame.framing = m_framing;
    event.frame.code = static_cast<Code>(m_frame[1]);
    std::size_t offset = 4;
    if (carriesHeader(m_framing, event.frame.code)) {
        std::copy(m_frame.begin() + 4, m_frame.begin() + 4 + kHeaderSize,
                  event.frame.header.begin());
        offset += kHeaderSize;
    }
    event.frame.data.assign(m_frame.begin() + static_cast<std::ptrdiff_t>(offset),
                            m_frame.begin() + static_cast<std::ptrdiff_t>(body));
    event.receivedSum = received;
    event.expectedSum = expected;
    m_frame.clear();
    m_total = 0;
    events.push_back(std::move(event));
}

} // namespace frezka::grinder
