#pragma once
// Incremental decoder of ANC / K51 messages. Feed it bytes as they arrive, in any chunks; it
// yields whole frames, frames whose checksum failed, and the noise it skipped between frames.
//
// Resynchronisation: a message starts with AA, a code of the family and a length that fits the
// code (0 for control messages, at least the header for K51 data messages). A start that fails
// those checks is noise: its AA is dropped and the following bytes are scanned again, so an AA
// inside noise cannot swallow the next real message. Once a start is accepted the decoder
// collects exactly `length` bytes and the checksum; a checksum failure is reported with the
// parsed frame and the decoder continues after it (the sender repeats the message on NAK).

#include "driver/grinder/frame.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace frezka::grinder {

struct DecodeEvent
{
    enum class Kind {
        Frame,         // a whole message with a good checksum
        ChecksumError, // a whole message whose checksum does not match
        Noise,         // bytes skipped before the next accepted message start
    };
    Kind kind = Kind::Frame;
    Frame frame;                   // Frame and ChecksumError
    std::uint16_t receivedSum = 0; // ChecksumError: the checksum on the wire
    std::uint16_t expectedSum = 0; // ChecksumError: the checksum of the bytes received
    Bytes noise;                   // Noise: the skipped bytes
    bool operator==(const DecodeEvent &) const = default;
};

class FrameDecoder
{
public:
    explicit FrameDecoder(Framing framing);

    // Consumes bytes and appends what they complete to `events`.
    void feed(const std::uint8_t *bytes, std::size_t size, std::vector<DecodeEvent> &events);
    void feed(const Bytes &bytes, std::vector<DecodeEvent> &events)
    {
        feed(bytes.data(), bytes.size(), events);
    }
    // Drops a partial message (after a timeout). Skipped noise not yet reported is returned
    // as a Noise event so no byte goes unaccounted.
    void reset(std::vector<DecodeEvent> &events);

    Framing framing() const { return m_framing; }
    // Bytes of the message in progress received so far (0 between messages).
    std::size_t pendingBytes() const { return m_frame.size(); }
    // Whole size of the message in progress once its length is known, else 0.
    std::size_t pendingTotal() const;

private:
    void consume(std::uint8_t byte, std::vector<DecodeEvent> &events);
    void rejectStart(std::vector<DecodeEvent> &events);
    void finish(std::vector<DecodeEvent> &events);
    void flushNoise(std::vector<DecodeEvent> &events);

    Framing m_framing;
    Bytes m_frame;           // bytes of the message in progress, from its AA on
    Bytes m_noise;           // skipped bytes not reported yet
    std::size_t m_total = 0; // whole size of the message in progress once known
};

} // namespace frezka::grinder
