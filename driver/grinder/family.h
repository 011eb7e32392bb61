#pragma once
// The three transfer kinds and the messages each uses (k51-protocol.md §2-§4). Keep every
// family-dependent choice here, in one table.
//
// Adopted reading for the ANC save (the manual's sequence diagram is lost): the PC asks with
// an empty SAV message, the ANC answers with SAV carrying the data — the same shape as the
// K51's DEJ -> SAV.

#include "driver/grinder/frame.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace frezka::grinder {

enum class Family {
    Anc,        // ANCLOAD/ANCSAVE: programs 0-9, 0x5500 or 0x5506 bytes, no header
    K51,        // K51LOAD/K51SAVE, KCOMM: programs, length from the controller, 16-byte header
    HardChrome, // HEDIT (ANC 4.x): 0x2E bytes from 0x1100, K51 framing with header
    Table,      // APROXTAB: a grinding-shape table PC -> K51 only (LOA1, KONFIG6 = 3)
};

struct FamilyInfo
{
    Family family;
    const char *id; // "anc", "k51", "hedit"
    Framing framing;
    Code loadCode;           // PC -> controller data message
    Code requestCode;        // PC asks for the data
    Code saveCode;           // controller -> PC data message
    std::size_t defaultSize; // image size the emulator holds by default (0: none)
    int defaultBaud;
    bool saves = true; // the controller can send these data to the PC
};

const FamilyInfo &familyInfo(Family family);

// Adopted reading (the manual is silent): a controller drops a message that stops arriving
// for this long, so a cancelled load does not swallow the next ENQ.
constexpr std::int64_t kControllerGapUs = 1'000'000;
std::optional<Family> familyFromId(std::string_view id);

} // namespace frezka::grinder
