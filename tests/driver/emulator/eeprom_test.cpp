// EEPROM commands (§12) and persistence of the emulated EEPROM.

#include "emulator_test_util.h"

#include "driver/emulator/eeprom.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace frezka::emulator;
using namespace frezka::emulator::test;

namespace {

std::string tempPath(const char *name)
{
    const auto dir =
        std::filesystem::temp_directory_path() /
        ("frezka-eeprom-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

} // namespace

TEST(Eeprom, BytesFloatsAndUints)
{
    Unit unit(optionsFor(Variant::Gve64));
    EXPECT_EQ(ask(unit, "!0ER05\r"), "0,FF\r");
    EXPECT_EQ(ask(unit, "!0EW05,AC\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0ER05\r"), "0,AC\r");
    EXPECT_EQ(ask(unit, "!0ER5\r"), "0,AC\r");
    EXPECT_EQ(ask(unit, "!0EFR30\r"), "0,100\r"); // factory: 100 steps/mm
    EXPECT_EQ(ask(unit, "!0EFW30,400.0\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0EFR30\r"), "0,400\r");
    EXPECT_EQ(ask(unit, "!0EFW30,2.5\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0EFR30\r"), "0,2.5\r");
    EXPECT_EQ(ask(unit, "!0ER30\r"), "0,00\r"); // 2.5f = 0x40200000, little endian
    EXPECT_EQ(ask(unit, "!0ER33\r"), "0,40\r");
    EXPECT_EQ(ask(unit, "!0EUW48,200\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0EUR48\r"), "0,200\r");
    EXPECT_EQ(ask(unit, "!0EUW48,4294967295\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0EUR48\r"), "0,4294967295\r");
    EXPECT_EQ(ask(unit, "!7ER05\r"), "0,AC\r"); // address 7 reaches the same EEPROM
    EXPECT_EQ(unit.eepromByte(0x05), 0xAC);
}

TEST(Eeprom, BadAddressesAndValues)
{
    Unit unit(optionsFor(Variant::Gve114));
    EXPECT_EQ(ask(unit, "!0ER100\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0ERFF\r"), "0,FF\r"); // an erased cell
    EXPECT_EQ(ask(unit, "!0EFRFD\r"), "5\r");   // four bytes do not fit
    EXPECT_EQ(ask(unit, "!0EFRFC\r").substr(0, 2), "0,");
    EXPECT_EQ(ask(unit, "!0EW05\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0EW05,100\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0EWZZ,00\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0EFW30,abc\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0EFW30,1e99\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0EUW48,-1\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0EUW48,4294967296\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0EX05\r"), "3\r");
    Unit gve84(optionsFor(Variant::Gve84));
    EXPECT_EQ(ask(gve84, "!0ER01\r"), "0,00\r"); // relay switches the spindle
    EXPECT_EQ(ask(gve84, "!0EFR30\r"), "3\r");
    EXPECT_EQ(ask(gve84, "!0EUW48,1\r"), "3\r");
}

TEST(Eeprom, PersistsInAFile)
{
    const std::string path = tempPath("unit.eeprom");
    std::filesystem::remove(path);
    UnitOptions o = optionsFor(Variant::Gve64);
    o.eepromFile = path;
    {
        Unit unit(o);
        EXPECT_EQ(unit.eepromError(), "");
        EXPECT_FALSE(std::filesystem::exists(path)); // created on the first write
        EXPECT_EQ(ask(unit, "!0EW07,05\r"), "0\r");
        EXPECT_EQ(ask(unit, "!0EFW34,320.5\r"), "0\r");
    }
    {
        Unit unit(o);
        EXPECT_EQ(ask(unit, "!0ER07\r"), "0,05\r");
        EXPECT_EQ(ask(unit, "!0EFR34\r"), "0,320.5\r");
        EXPECT_EQ(ask(unit, "!0J\r"), "0\r");
        unit.advance(3);
        EXPECT_EQ(ask(unit, "!0ER07\r"), "0,05\r"); // survives J
    }
    std::ifstream in(path);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first.size(), 16u * 3 - 1); // "FF 02 03 ..."
    EXPECT_EQ(first.substr(0, 8), "FF 02 03");
}

TEST(Eeprom, BadFileIsReported)
{
    const std::string path = tempPath("bad.eeprom");
    {
        std::ofstream out(path);
        out << "FF FF ZZ\n";
    }
    UnitOptions o = optionsFor(Variant::Gve64);
    o.eepromFile = path;
    Unit unit(o);
    EXPECT_NE(unit.eepromError().find("'ZZ'"), std::string::npos) << unit.eepromError();
    EXPECT_EQ(ask(unit, "!0ER05\r"), "0,FF\r"); // factory contents, nothing half-loaded
    {
        std::ofstream out(path);
        out << "00 01\n";
    }
    Unit shortFile(o);
    EXPECT_NE(shortFile.eepromError().find("2 bytes"), std::string::npos);
}
