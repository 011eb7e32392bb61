// The unit's EEPROM differences found on connecting read in plain numbers ("profile 10", not
// "profile 10.000000").
#include "simfixture.h"

#include <gtest/gtest.h>

#include <regex>

namespace frezka::driver {
namespace {

using test::Sim;

TEST(EepromWords, DifferencesInPlainNumbers)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    const auto &differences = sim.core.state().eepromDifferences;
    ASSERT_FALSE(differences.empty()) << "the emulator's defaults differ from the profile";
    // Numbers without trailing zeros; a byte in two hex digits on both sides, as the unit shows it.
    const std::regex plain(".*: unit -?[0-9]+(\\.[0-9]*[1-9])?, profile -?[0-9]+(\\.[0-9]*[1-9])?");
    const std::regex byte(".*: unit [0-9A-F]{2}, profile [0-9A-F]{2}");
    bool sawByte = false;
    for (const EepromDifference &d : differences) {
        const bool isByte = d.entry.kind == machine::EepromKind::Byte;
        sawByte = sawByte || isByte;
        EXPECT_TRUE(std::regex_match(d.text(), isByte ? byte : plain)) << d.text();
    }
    EXPECT_TRUE(sawByte) << "the emulator's defaults differ in a byte too";
}

} // namespace
} // namespace frezka::driver
