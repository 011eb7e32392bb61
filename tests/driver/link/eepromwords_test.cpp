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
    const std::regex plain(".*: unit [^,]+, profile -?[0-9]+(\\.[0-9]*[1-9])?");
    for (const std::string &d : differences)
        EXPECT_TRUE(std::regex_match(d, plain)) << d;
}

} // namespace
} // namespace frezka::driver
