#pragma once
// The unit's 256-byte EEPROM (docs/gve-protocol.md §12): bytes, little-endian floats and
// uint32 values, factory contents per variant, optional persistence in a text file
// (16 lines of 16 upper-case hex bytes separated by spaces).

#include "protocol/variant.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace frezka::emulator {

class Eeprom
{
public:
    static constexpr int kSize = 256;

    explicit Eeprom(protocol::Variant variant);

    std::uint8_t byte(int address) const { return m_bytes[address & 0xFF]; }
    void setByte(int address, std::uint8_t value) { m_bytes[address & 0xFF] = value; }
    // 4-byte values at address..address+3; address must be <= 0xFC.
    float readFloat(int address) const;
    std::uint32_t readUint32(int address) const;
    void writeFloat(int address, float value);
    void writeUint32(int address, std::uint32_t value);

    // Load from / save to the text file; the error text is empty on success.
    std::string load(const std::string &path);
    std::string save(const std::string &path) const;

    bool operator==(const Eeprom &) const = default;

private:
    std::array<std::uint8_t, kSize> m_bytes{};
};

} // namespace frezka::emulator
