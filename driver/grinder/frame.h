#pragma once
// ANC / K51 framed messages (docs/grinder.md, shared k51-protocol.md §2). Pure C++, no Qt.
//
//   ANC  : AA code lenHi lenLo data... sum8          (no header)
//   K51  : AA code lenHi lenLo [header16 data...] sumHi sumLo   (K51LOAD/K51SAVE, HEDIT)
//
// Adopted readings (fit all four manual examples): the length counts header + data; control
// messages (ENQ, ACK, NAK, DEJ, DEJ2) carry neither; the K51 checksum is the two's complement
// of the 16-bit sum of every byte before it, the ANC one of the 8-bit sum, so the sum of the
// whole message is zero.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace frezka::grinder {

using Bytes = std::vector<std::uint8_t>;

// Which frame layout is on the wire.
enum class Framing {
    Anc, // ANCLOAD/ANCSAVE: no header, 1-byte checksum
    K51, // K51LOAD/K51SAVE and HEDIT: 16-byte header, 16-bit checksum
};

// Message codes of both families (byte 2 of every message).
enum class Code : std::uint8_t {
    AncLoad = 0x01,           // LOA: data to the ANC
    AncSave = 0x02,           // SAV: data from the ANC (empty = request, adopted reading)
    Enq = 0x05,               // link check
    Ack = 0x06,               // acknowledge
    Nak = 0x07,               // repeat please
    Load = 0x10,              // LOA: program to the controller
    LoadTable = 0x11,         // LOA1: table to the controller
    LoadHardChrome = 0x12,    // LOA2: hard-chrome (HEDIT) data to the controller
    Request = 0x20,           // DEJ: request a program
    RequestHardChrome = 0x22, // DEJ2: request hard-chrome data
    Save = 0x40,              // SAV: program from the controller
    SaveHardChrome = 0x42,    // SAV2: hard-chrome data from the controller
};

constexpr std::uint8_t kStartByte = 0xAA; // NAV
constexpr std::size_t kHeaderSize = 16;
constexpr std::size_t kMaxPayload = 0xFFFF; // the 16-bit length field

using Header = std::array<std::uint8_t, kHeaderSize>;

// True when the code belongs to the framing's family.
bool isKnownCode(Framing framing, std::uint8_t code);
// True for codes whose message carries a 16-byte header (K51 data messages).
bool carriesHeader(Framing framing, Code code);
// True for codes whose message carries no length at all (ENQ, ACK, NAK, DEJ, DEJ2).
bool isControlCode(Framing framing, Code code);
// Mnemonic as in the manual: "ENQ", "LOA", "SAV2", ... ("0x??" for unknown codes).
std::string codeName(Framing framing, std::uint8_t code);

// One message, header and data apart. A value type.
struct Frame
{
    Framing framing = Framing::K51;
    Code code = Code::Enq;
    Header header{}; // meaningful only when carriesHeader(framing, code)
    Bytes data;

    static Frame control(Framing framing, Code code);
    static Frame withData(Framing framing, Code code, const Header &header, Bytes data);

    // Value of the length field: header + data bytes.
    std::size_t payloadSize() const;
    bool operator==(const Frame &) const = default;
};

enum class FrameError {
    None,
    UnknownCode,     // the code is not one of the framing's family
    DataInControl,   // a control message with a header or data
    PayloadTooLarge, // header + data exceed 0xFFFF bytes
};
// English text for a FrameError (the Qt layers translate their own wording).
const char *frameErrorText(FrameError error);

// Checks that the frame can be put on the wire.
FrameError validateFrame(const Frame &frame);
// The wire bytes of a valid frame; empty when validateFrame() fails.
Bytes encodeFrame(const Frame &frame);

// Checksum over the bytes before it: 8-bit (ANC) or 16-bit (K51) two's complement of the sum.
std::uint16_t frameChecksum(Framing framing, const std::uint8_t *bytes, std::size_t size);
std::size_t checksumSize(Framing framing);

// 16 bytes from `text` (cut, padded with spaces); an empty text gives 16 zero bytes.
Header headerFromText(const std::string &text);
// Header as text: trailing spaces and NULs removed, other control bytes shown as '.'.
std::string headerText(const Header &header);
// Hex dump "AA 05 00 00 FF 51" (for logs and the serial monitor).
std::string hexDump(const std::uint8_t *bytes, std::size_t size);
inline std::string hexDump(const Bytes &bytes)
{
    return hexDump(bytes.data(), bytes.size());
}

} // namespace frezka::grinder
