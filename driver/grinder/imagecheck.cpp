#include "driver/grinder/imagecheck.h"

#include <cstdio>

namespace frezka::grinder {

namespace {

struct BlockPlace
{
    std::uint8_t id;
    std::size_t offset; // within the block area
    std::size_t size;
};

std::vector<BlockPlace> blockPlaces()
{
    std::vector<BlockPlace> places;
    for (int p = 0; p < kProgramCount; ++p)
        places.push_back({std::uint8_t(p), std::size_t(p) * kTchinBlockSize, kTchinBlockSize});
    for (int p = 0; p < kProgramCount; ++p)
        places.push_back(
            {std::uint8_t(0x80 + p), kOtherBlocksOffset + p * kOtherBlockSize, kOtherBlockSize});
    return places;
}

std::vector<BlockReport> checkBlocks(const Bytes &image, std::size_t base)
{
    std::vector<BlockReport> reports;
    for (const BlockPlace &place : blockPlaces()) {
        BlockReport report;
        report.id = place.id;
        report.offset = base + place.offset;
        report.size = place.size;
        const std::uint8_t *block = image.data() + report.offset;
        report.startOk = block[0] == kStartByte;
        report.idOk = block[1] == place.id;
        std::uint8_t sum = 0;
        for (std::size_t i = 0; i < place.size; ++i)
            sum = std::uint8_t(sum + block[i]);
        report.checksumOk = sum == 0;
        reports.push_back(report);
    }
    return reports;
}

std::size_t countBad(const std::vector<BlockReport> &blocks)
{
    std::size_t bad = 0;
    for (const BlockReport &block : blocks)
        bad += block.ok() ? 0 : 1;
    return bad;
}

} // namespace

std::size_t ImageReport::badBlocks() const
{
    return countBad(blocks);
}

std::string ImageReport::summary() const
{
    if (!hasBlocks)
        return "no inner blocks (" + std::to_string(size) + " bytes)";
    const std::size_t bad = badBlocks();
    if (bad == 0)
        return std::to_string(blocks.size()) + " blocks, all valid";
    std::string text =
        std::to_string(bad) + " of " + std::to_string(blocks.size()) + " blocks invalid:";
    for (const BlockReport &block : blocks) {
        if (block.ok())
            continue;
        char id[8];
        std::snprintf(id, sizeof id, " 0x%02X", block.id);
        text += id;
        text += !block.startOk ? " (no AA)" : !block.idOk ? " (id)" : " (checksum)";
    }
    return text;
}

ImageReport checkImage(const Bytes &image)
{
    ImageReport report;
    report.size = image.size();
    if (image.size() < kProgramImageSize)
        return report;
    report.hasBlocks = true;
    // Extra bytes first (the manual's reading); fall back to blocks at offset 0.
    const std::size_t extra = image.size() - kProgramImageSize;
    report.blocksOffset = extra;
    report.blocks = checkBlocks(image, extra);
    if (extra != 0 && report.badBlocks() != 0) {
        std::vector<BlockReport> atZero = checkBlocks(image, 0);
        if (countBad(atZero) < report.badBlocks()) {
            report.blocksOffset = 0;
            report.blocks = std::move(atZero);
        }
    }
    return report;
}

void sealImageBlocks(Bytes &image, std::size_t blocksOffset)
{
    if (image.size() < blocksOffset + kProgramImageSize)
        return;
    for (const BlockPlace &place : blockPlaces()) {
        std::uint8_t *block = image.data() + blocksOffset + place.offset;
        block[0] = kStartByte;
        block[1] = place.id;
        block[2] = 0;
        std::uint8_t sum = 0;
        for (std::size_t i = 0; i < place.size; ++i)
            sum = std::uint8_t(sum + block[i]);
        block[2] = std::uint8_t(0x100 - sum);
    }
}

} // namespace frezka::grinder
