#include "protocol/checksum.h"
#include "protocol/variant.h"

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

TEST(Variant, FirmwareVersionAndFeatures)
{
    EXPECT_EQ(firmwareVersion("IP64MPG v19 10.9.2010"), 19);
    EXPECT_EQ(firmwareVersion("IP84 v3 27.1.2010"), 3);
    EXPECT_FALSE(firmwareVersion("IP114/500 x16 16.9.2018"));
    EXPECT_FALSE(firmwareVersion("IP64 v"));
    const Features all{true, true, true};
    EXPECT_EQ(featuresOf(Variant::Gve64, 19), all);
    EXPECT_EQ(featuresOf(Variant::Gve64, std::nullopt), all);
    EXPECT_EQ(featuresOf(Variant::Gve64, 17), (Features{true, true, false}));
    EXPECT_EQ(featuresOf(Variant::Gve64Phantom, 9), (Features{false, false, false, false}));
    EXPECT_TRUE(featuresOf(Variant::Gve64, 10).switchHoming); // W from IP64MPG v10 (§14.1)
    EXPECT_FALSE(featuresOf(Variant::Gve64, 9).switchHoming);
    EXPECT_EQ(featuresOf(Variant::Gve114, 1), all); // the version gates the GVE64 only
    EXPECT_EQ(featuresOf(Variant::Gve84, 3), (Features{false, false, true}));
}
