// The Frezka grinder file: data with header and system; bare files of the old tools still open.
#include "driver/grinder/grinderfile.h"

#include <gtest/gtest.h>

using namespace frezka::grinder;

TEST(GrinderFile, KeepsHeaderSystemAndEveryByte)
{
    GrinderFile file;
    file.container = true;
    file.family = Family::HardChrome;
    file.header = headerFromText("HRIDEL c.5");
    for (int i = 0; i < 46; ++i)
        file.data.push_back(std::uint8_t(i * 37));
    file.data[3] = '\n'; // data bytes are never read as text
    const Bytes bytes = encodeGrinderFile(file);
    const std::string text(bytes.begin(), bytes.begin() + 17);
    EXPECT_EQ(text, "FREZKA-GRINDER 1\n");
    std::string error;
    const auto decoded = decodeGrinderFile(bytes, error);
    ASSERT_TRUE(decoded.has_value()) << error;
    EXPECT_EQ(*decoded, file);
}

TEST(GrinderFile, BareDataOfTheOldToolsOpenWithoutHeader)
{
    const Bytes bare(21767, 0xAA);
    std::string error;
    const auto decoded = decodeGrinderFile(bare, error);
    ASSERT_TRUE(decoded.has_value());
    EXPECT_FALSE(decoded->container);
    EXPECT_EQ(decoded->data, bare);
}

TEST(GrinderFile, ADamagedFileIsRefusedWithTheReason)
{
    GrinderFile file;
    file.data = Bytes(100, 1);
    Bytes bytes = encodeGrinderFile(file);
    bytes.pop_back();
    std::string error;
    EXPECT_FALSE(decodeGrinderFile(bytes, error).has_value());
    EXPECT_EQ(error, "the file says 100 data bytes but holds 99");
    const std::string noSystem = "FREZKA-GRINDER 1\nheader: 00\nlength: 0\n\n";
    EXPECT_FALSE(decodeGrinderFile(Bytes(noSystem.begin(), noSystem.end()), error));
    EXPECT_EQ(error, "the file's description lacks a valid system");
}

TEST(GrinderFile, AnEmptyHeaderIsTheManualsZeroHeader)
{
    Header zero{};
    EXPECT_EQ(headerFromText(""), zero);
    EXPECT_EQ(headerFromText("A")[1], ' ');
}
