#pragma once
// Test helper: what the driver put on the line to the emulated unit, command by command.
//
// Installs EmulatorPort::tamper as a pass-through tap, so the record is exactly the bytes that
// entered the wire (checksums stripped, packets' lines as they went).

#include "driver/link/emulatorport.h"

#include <string>
#include <string_view>
#include <vector>

namespace frezka::driver::test {

class WireTap
{
public:
    explicit WireTap(EmulatorPort &port)
    {
        port.tamper = [this](std::string_view bytes) {
            m_pending += bytes;
            std::size_t cr;
            while ((cr = m_pending.find('\r')) != std::string::npos) {
                std::string line = m_pending.substr(0, cr);
                m_pending.erase(0, cr + 1);
                // "!0H,A9" with checksums on: the body is what the unit executes.
                if (hasChecksum(line))
                    line.resize(line.size() - 3);
                m_lines.push_back(line);
            }
            return std::string(bytes);
        };
    }
    const std::vector<std::string> &lines() const { return m_lines; }
    std::size_t size() const { return m_lines.size(); }
    // Lines from index `from` on that start with `prefix` ("!0W", "!0L").
    std::vector<std::string> matching(const std::string &prefix, std::size_t from = 0) const
    {
        std::vector<std::string> out;
        for (std::size_t i = from; i < m_lines.size(); ++i)
            if (m_lines[i].rfind(prefix, 0) == 0)
                out.push_back(m_lines[i]);
        return out;
    }

private:
    // docs/gve-protocol.md §2.1: ",HH" = the sum of the bytes up to and including that comma.
    static bool hasChecksum(const std::string &line)
    {
        if (line.size() < 4 || line[line.size() - 3] != ',')
            return false;
        unsigned sum = 0;
        for (std::size_t i = 0; i + 2 < line.size(); ++i)
            sum += static_cast<unsigned char>(line[i]);
        static const char kHex[] = "0123456789ABCDEF";
        return line[line.size() - 2] == kHex[(sum >> 4) & 15] &&
               line[line.size() - 1] == kHex[sum & 15];
    }

    std::string m_pending;
    std::vector<std::string> m_lines;
};

} // namespace frezka::driver::test
