#include "eeprom.h"

#include <bit>
#include <cctype>
#include <cstring>
#include <fstream>
#include <sstream>

namespace frezka::emulator {

Eeprom::Eeprom(protocol::Variant variant)
{
    m_bytes.fill(0xFF); // erased cells
    using protocol::Variant;
    if (variant == Variant::Gve84) {
        m_bytes[0x01] = 0x00; // relay switches the spindle (factory setting)
        m_bytes[0xFD] = 0x00;
        return;
    }
    m_bytes[0x01] = 0x02; // OUT1 coolant
    m_bytes[0x02] = 0x03; // OUT2 air blow
    m_bytes[0x03] = 0x08; // OUT3 brake
    m_bytes[0x06] = 0x00; // MPG off
    m_bytes[0x07] = 0x00; // no homing input
    m_bytes[0x08] = 0x00;
    m_bytes[0x09] = 0x00;
    m_bytes[0x0A] = 0x00;
    m_bytes[0x0B] = 0x00;
    m_bytes[0xFD] = 0x00;
    for (int axis = 0; axis < 4; ++axis) {
        writeFloat(0x10 + 4 * axis, 0.0f);   // lower limit, mm
        writeFloat(0x20 + 4 * axis, 300.0f); // upper limit, mm
        writeFloat(0x30 + 4 * axis, 100.0f); // steps per mm
    }
    writeFloat(0x40, 100.0f); // MPG acceleration mm/s^2
    writeFloat(0x44, 10.0f);  // MPG max speed mm/s
    writeUint32(0x48, 100);   // MPG delay ms
    writeUint32(0x4C, 1000);  // default spindle speed, permille
    if (variant == Variant::Gve114) {
        m_bytes[0x0D] = 0xFF;
        writeFloat(0x60, 1.0f);
    } else {
        for (int axis = 0; axis < 3; ++axis)
            writeFloat(0x50 + 4 * axis, 5.0f); // homing speed mm/s
    }
}

float Eeprom::readFloat(int address) const
{
    return std::bit_cast<float>(readUint32(address));
}

std::uint32_t Eeprom::readUint32(int address) const
{
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i)
        v = (v << 8) | m_bytes[(address + i) & 0xFF];
    return v;
}

void Eeprom::writeFloat(int address, float value)
{
    writeUint32(address, std::bit_cast<std::uint32_t>(value));
}

void Eeprom::writeUint32(int address, std::uint32_t value)
{
    for (int i = 0; i < 4; ++i)
        m_bytes[(address + i) & 0xFF] = static_cast<std::uint8_t>(value >> (8 * i));
}

std::string Eeprom::load(const std::string &path)
{
    std::ifstream in(path);
    if (!in)
        return "cannot open EEPROM file " + path;
    std::array<std::uint8_t, kSize> bytes{};
    int count = 0;
    std::string token;
    while (in >> token) {
        if (count >= kSize)
            return "EEPROM file " + path + " has more than 256 bytes";
        if (token.size() != 2 || !std::isxdigit(static_cast<unsigned char>(token[0])) ||
            !std::isxdigit(static_cast<unsigned char>(token[1])))
            return "EEPROM file " + path + ": byte " + std::to_string(count) + " is '" + token +
                   "', expected two hex digits";
        bytes[count++] = static_cast<std::uint8_t>(std::stoi(token, nullptr, 16));
    }
    if (count != kSize)
        return "EEPROM file " + path + " has " + std::to_string(count) + " bytes, expected 256";
    m_bytes = bytes;
    return {};
}

std::string Eeprom::save(const std::string &path) const
{
    std::ostringstream text;
    static constexpr char kHex[] = "0123456789ABCDEF";
    for (int i = 0; i < kSize; ++i) {
        text << kHex[m_bytes[i] >> 4] << kHex[m_bytes[i] & 0xF];
        text << ((i % 16 == 15) ? '\n' : ' ');
    }
    std::ofstream out(path, std::ios::trunc);
    if (!out)
        return "cannot write EEPROM file " + path;
    out << text.str();
    out.flush();
    if (!out)
        return "cannot write EEPROM file " + path;
    return {};
}

} // namespace frezka::emulator
