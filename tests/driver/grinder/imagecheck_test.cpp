#include "driver/grinder/imagecheck.h"

#include <gtest/gtest.h>

using namespace frezka::grinder;

namespace {
Bytes sealedImage(std::size_t size, std::size_t offset)
{
    Bytes image(size);
    for (std::size_t i = 0; i < size; ++i)
        image[i] = std::uint8_t(i * 31 + 7);
    sealImageBlocks(image, offset);
    return image;
}
} // namespace

TEST(GrinderImage, SealedImagesAreValid)
{
    for (std::size_t size : {kProgramImageSize, kAncImageSizeWithWheel, kK51ImageSize}) {
        const ImageReport report = checkImage(sealedImage(size, size - kProgramImageSize));
        EXPECT_TRUE(report.hasBlocks);
        EXPECT_EQ(report.blocks.size(), 20u);
        EXPECT_TRUE(report.ok()) << report.summary();
        EXPECT_EQ(report.blocksOffset, size - kProgramImageSize);
        EXPECT_EQ(report.summary(), "20 blocks, all valid");
    }
}

TEST(GrinderImage, BlocksAtOffsetZeroAreRecognised)
{
    const ImageReport report = checkImage(sealedImage(kK51ImageSize, 0));
    EXPECT_TRUE(report.ok());
    EXPECT_EQ(report.blocksOffset, 0u);
}

TEST(GrinderImage, ReportsEachBadBlock)
{
    Bytes image = sealedImage(kAncImageSizeWithWheel, 6);
    image[6 + 3 * kTchinBlockSize + 100] ^= 0x40;                   // checksum of block 0x03
    image[6 + kOtherBlocksOffset + 5 * kOtherBlockSize + 1] = 0x07; // id of block 0x85
    const ImageReport report = checkImage(image);
    EXPECT_EQ(report.badBlocks(), 2u);
    EXPECT_EQ(report.summary(), "2 of 20 blocks invalid: 0x03 (checksum) 0x85 (id)");
    EXPECT_FALSE(report.blocks[3].checksumOk);
    EXPECT_TRUE(report.blocks[3].idOk);
}

TEST(GrinderImage, ShortDataHasNoBlocks)
{
    const ImageReport report = checkImage(Bytes(kHardChromeSize));
    EXPECT_FALSE(report.hasBlocks);
    EXPECT_TRUE(report.ok());
    EXPECT_EQ(report.summary(), "no inner blocks (46 bytes)");
}
