#pragma once
// Checks the inner blocks of a program image (k51-protocol.md §4) without changing a byte: the
// file is always stored and sent back exactly as received; this only reports.
//
// Layout of the 0x5500 program bytes (controller addresses 0x2000..0x74FF):
//   TCHIN values of program p at 0x0000 + p*0x800 (0x800 bytes), block id p
//   other values of program p at 0x5000 + p*0x80 (0x80 bytes),  block id 0x80 + p
// Each block starts AA, id, checksum byte. Extra bytes (ANC 0x5506: 6, K51: 7 or more) are
// sent first (manual 2.5.2 for ANC; adopted for K51 too), so the blocks start after them; an
// image whose blocks sit at offset 0 is also recognised.
// Adopted reading (the manual does not define "ks"): the 8-bit sum of the whole block,
// AA, id and ks included, is zero.

#include "driver/grinder/frame.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace frezka::grinder {

constexpr std::size_t kProgramImageSize = 0x5500;      // programs 0-9, both block kinds
constexpr std::size_t kAncImageSizeWithWheel = 0x5506; // + wheel diameter and width
constexpr std::size_t kK51ImageSize = 0x5507;          // + diameter, its unit, width
constexpr std::size_t kHardChromeSize = 0x2E;          // HEDIT data from 0x1100
constexpr int kProgramCount = 10;
constexpr std::size_t kTchinBlockSize = 0x800;
constexpr std::size_t kOtherBlockSize = 0x80;
constexpr std::size_t kOtherBlocksOffset = 0x5000;

struct BlockReport
{
    std::uint8_t id = 0;    // expected block id (0x00-0x09, 0x80-0x89)
    std::size_t offset = 0; // in the image
    std::size_t size = 0;
    bool startOk = false;    // first byte is AA
    bool idOk = false;       // second byte is the id
    bool checksumOk = false; // 8-bit sum of the block is zero
    bool ok() const { return startOk && idOk && checksumOk; }
    bool operator==(const BlockReport &) const = default;
};

struct ImageReport
{
    std::size_t size = 0;
    bool hasBlocks = false;       // the size is a program image (>= 0x5500 bytes)
    std::size_t blocksOffset = 0; // where the 0x5500 block area starts
    std::vector<BlockReport> blocks;

    std::size_t badBlocks() const;
    bool ok() const { return badBlocks() == 0; }
    // English one-line summary, e.g. "20 blocks, all valid" or "2 of 20 blocks invalid: 0x03
    // (checksum), 0x85 (id)".
    std::string summary() const;
    bool operator==(const ImageReport &) const = default;
};

ImageReport checkImage(const Bytes &image);

// Writes AA, id and a matching checksum into every block of a program image whose block area
// starts at `blocksOffset` (used by the emulator to make a consistent image).
void sealImageBlocks(Bytes &image, std::size_t blocksOffset);

} // namespace frezka::grinder
