#include "driver/protocol/checksum.h"
#include "driver/protocol/variant.h"

#include <gtest/gtest.h>

using namespace frezka::protocol;

TEST(Checksum, ManualExamples)
{
    EXPECT_EQ(hexByte(checksum("!0A100,")), "4F"); // !0A100,4F
    EXPECT_EQ(hexByte(checksum("0,")), "5C");      // reply to %+: 0,5C
    EXPECT_EQ(hexByte(checksum("!0%-,")), "CF");   // !0%-,CF
    EXPECT_EQ(hexByte(checksum("0,10,")), "E9");   // packet reply 0,10,E9
}

TEST(Checksum, ParseHexByte)
{
    EXPECT_EQ(parseHexByte("4F"), 0x4F);
    EXPECT_EQ(parseHexByte("cf"), 0xCF);
    EXPECT_FALSE(parseHexByte("4"));
    EXPECT_FALSE(parseHexByte("G0"));
    EXPECT_FALSE(parseHexByte("123"));
}

TEST(Variant, TableLookups)
{
    EXPECT_EQ(variantFromId("gve114"), Variant::Gve114);
    EXPECT_FALSE(variantFromId("gve99"));
    EXPECT_EQ(variantInfo(Variant::Gve84).axisCount, 3);
    EXPECT_EQ(variantInfo(Variant::Gve64).queueCapacity, 420);
    EXPECT_EQ(variantInfo(Variant::Gve114).resetBrakeSpeed, 50000);
    EXPECT_EQ(variantFromFirmware("IP64MPG v19 10.9.2010"), Variant::Gve64);
    EXPECT_EQ(allVariants().size(), 4u);
}
