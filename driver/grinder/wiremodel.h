#pragma once
// When the bytes a port has taken have left the wire. A serial port reports bytes as written
// when its driver takes them into a buffer (a USB adapter may take a whole 21 KB message at
// once), not when they have been sent; at `baud` with 8N1 every byte then takes 10 bit times,
// one after the other. The estimate below serialises the bytes from the moment each chunk was
// taken, so it is never earlier than the real end of the wire (for the right baud rate);
// adapters add their latency on top, which the caller adds. Pure: times in microseconds.

#include <cstdint>
#include <vector>

namespace frezka::grinder {

class WireModel
{
public:
    explicit WireModel(int baud = 9600) { setBaud(baud); }
    void setBaud(int baud);
    // Forgets earlier bytes: the wire is idle from `nowUs`.
    void reset(std::int64_t nowUs);
    // The port took `bytes` more at `nowUs`.
    void accepted(std::int64_t nowUs, std::int64_t bytes);
    // When the last byte taken so far will have left the wire.
    std::int64_t endUs() const { return m_endUs; }
    // Bytes taken since reset() that have left the wire by `nowUs`.
    std::int64_t sentBy(std::int64_t nowUs) const;
    // Bytes taken since reset().
    std::int64_t acceptedBytes() const { return m_accepted; }
    // Microseconds one byte takes (10 bits).
    std::int64_t byteUs() const { return m_byteUs; }

private:
    std::int64_t m_byteUs = 1042;
    std::int64_t m_endUs = 0;
    std::int64_t m_accepted = 0;
};

// What a UART at `receiverBaud` reads from `bytes` sent back to back (8N1) at `senderBaud`: the
// same bytes when the rates agree, garbage of another length when they do not (a baud rate
// mismatch). The receiver finds the start bit, samples each bit in its middle at its own rate
// and looks for the next start bit after the middle of the stop bit; a byte whose stop bit
// reads 0 (framing error) is delivered as 0x00, as a Linux tty without IGNPAR/PARMRK does.
std::vector<std::uint8_t> resampleUart(const std::vector<std::uint8_t> &bytes, int senderBaud,
                                       int receiverBaud);

} // namespace frezka::grinder
