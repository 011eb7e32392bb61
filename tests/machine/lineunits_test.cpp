// The profile's list of units on its line (line.units): read, written, its rules, and the other
// units' profiles read relative to it.
#include "machine/machineconfig.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QTemporaryDir>

using namespace frezka;
using namespace frezka::machine;

namespace {

std::string profileWith(const std::string &units, const std::string &unit = "")
{
    return R"({"unit": {"variant": "gve114")" + unit + R"(}, "line": {"units": [)" + units + "]}}";
}

const char *kMill = R"({"address": 0, "variant": "gve114", "name": "Mill", "role": "machine"})";

bool hasError(const ConfigResult &r, ConfigErrorCode code, const std::string &key,
              const std::string &words = {})
{
    for (const ConfigError &e : r.errors)
        if (e.code == code && e.key == key && e.message.find(words) != std::string::npos)
            return true;
    return false;
}

std::string errorsText(const ConfigResult &r)
{
    std::string s;
    for (const ConfigError &e : r.errors)
        s += e.message + "\n";
    return s;
}

} // namespace

TEST(LineUnits, ReadWrittenAndReadBack)
{
    const ConfigResult r = parseMachineConfig(profileWith(
        std::string(kMill) +
        R"(, {"address": 1, "variant": "gve114", "name": "Engraver", "role": "auxiliary",
              "profile": "engraver.json"},
             {"address": 2, "variant": "gve114", "name": "Table", "role": "rotaryA"})"));
    ASSERT_TRUE(r.config) << errorsText(r);
    const auto &units = r.config->line.units;
    ASSERT_EQ(units.size(), 3u);
    EXPECT_EQ(units[1].address, 1);
    EXPECT_EQ(units[1].name, "Engraver");
    EXPECT_EQ(units[1].role, LineUnitRole::Auxiliary);
    EXPECT_EQ(units[1].profile, "engraver.json");
    EXPECT_EQ(units[2].role, LineUnitRole::RotaryA);
    EXPECT_EQ(machineUnitIndex(*r.config), 0);
    const ConfigResult back = parseMachineConfig(toJson(*r.config));
    ASSERT_TRUE(back.config) << errorsText(back) << toJson(*r.config);
    EXPECT_EQ(*back.config, *r.config);
    // No list: one unit at unit.address, and none is written.
    const MachineConfig plain = defaultMachineConfig(protocol::Variant::Gve114);
    EXPECT_EQ(toJson(plain).find("\"line\""), std::string::npos);
    EXPECT_TRUE(plain.line.units.empty());
}

TEST(LineUnits, RulesNameTheEntryAndWhatToDo)
{
    const auto aux = [](int address, const char *variant = "gve114") {
        return std::string(R"(, {"address": )") + std::to_string(address) + R"(, "variant": ")" +
               variant + R"(", "name": "B", "role": "auxiliary", "profile": "b.json"})";
    };
    const ConfigResult twice = parseMachineConfig(profileWith(kMill + aux(0)));
    EXPECT_TRUE(
        hasError(twice, ConfigErrorCode::Inconsistent, "line.units[1].address", "used twice"))
        << errorsText(twice);
    const ConfigResult spindle = parseMachineConfig(profileWith(kMill + aux(7)));
    EXPECT_TRUE(
        hasError(spindle, ConfigErrorCode::Inconsistent, "line.units[1].address", "spindle"))
        << errorsText(spindle);
    const ConfigResult gve64 = parseMachineConfig(profileWith(kMill + aux(1, "gve64")));
    EXPECT_TRUE(
        hasError(gve64, ConfigErrorCode::Inconsistent, "line.units[1].variant", "only GVE114"))
        << errorsText(gve64);
    const ConfigResult twoMachines = parseMachineConfig(profileWith(
        std::string(kMill) +
        R"(, {"address": 1, "variant": "gve114", "name": "Second", "role": "machine"})"));
    EXPECT_TRUE(hasError(twoMachines, ConfigErrorCode::Inconsistent, "line.units", "exactly one"))
        << errorsText(twoMachines);
    const ConfigResult noProfile = parseMachineConfig(
        profileWith(std::string(kMill) +
                    R"(, {"address": 1, "variant": "gve114", "name": "B", "role": "auxiliary"})"));
    EXPECT_TRUE(hasError(noProfile, ConfigErrorCode::Inconsistent, "line.units[1].profile"))
        << errorsText(noProfile);
    const ConfigResult elsewhere =
        parseMachineConfig(profileWith(kMill + aux(1), R"(, "address": 3)"));
    EXPECT_TRUE(hasError(elsewhere, ConfigErrorCode::Inconsistent, "line.units[0]", "unit.address"))
        << errorsText(elsewhere);
    const ConfigResult typo = parseMachineConfig(profileWith(
        R"({"address": 0, "variant": "gve114", "name": "Mill", "role": "machine", "adress": 1})"));
    EXPECT_TRUE(hasError(typo, ConfigErrorCode::UnknownKey, "line.units[0].adress"))
        << errorsText(typo);
    const ConfigResult role = parseMachineConfig(
        profileWith(R"({"address": 0, "variant": "gve114", "name": "Mill", "role": "main"})"));
    EXPECT_TRUE(hasError(role, ConfigErrorCode::BadChoice, "line.units[0].role"))
        << errorsText(role);
    // The same rules for a config built in code (the profile editor's check).
    MachineConfig built = defaultMachineConfig(protocol::Variant::Gve114);
    built.line.units = {{0, protocol::Variant::Gve114, "Mill", LineUnitRole::Machine, {}},
                        {0, protocol::Variant::Gve114, "B", LineUnitRole::Auxiliary, "b.json"}};
    EXPECT_FALSE(validateMachineConfig(built).empty());
    built.line.units[1].address = 1;
    EXPECT_TRUE(validateMachineConfig(built).empty());
}

TEST(LineUnits, OtherUnitsProfilesAreReadBesideThisOne)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    MachineConfig engraver = defaultMachineConfig(protocol::Variant::Gve114);
    engraver.name = "Engraver";
    engraver.axes[0].stepsPerMm = 160;
    ASSERT_FALSE(saveMachineConfig(engraver, dir.filePath("engraver.json").toStdString()));
    MachineConfig mill = defaultMachineConfig(protocol::Variant::Gve114);
    mill.link.baud = 57600;
    mill.line.units = {
        {0, protocol::Variant::Gve114, "Mill", LineUnitRole::Machine, {}},
        {1, protocol::Variant::Gve114, "Engraver", LineUnitRole::Auxiliary, "engraver.json"}};
    ASSERT_TRUE(validateMachineConfig(mill).empty());
    const std::string millPath = dir.filePath("mill.json").toStdString();
    const LineProfiles p = loadLineProfiles(mill, millPath);
    ASSERT_TRUE(p.errors.empty()) << p.errors.front().message;
    ASSERT_EQ(p.configs.size(), 2u);
    EXPECT_EQ(p.configs[0], mill);
    EXPECT_EQ(p.configs[1].axes[0].stepsPerMm, 160);
    EXPECT_EQ(p.configs[1].unit.address, 1);
    EXPECT_EQ(p.configs[1].link.baud, 57600); // one line, one baud rate
    // A missing profile names its entry and the file.
    mill.line.units[1].profile = "missing.json";
    const LineProfiles missing = loadLineProfiles(mill, millPath);
    ASSERT_EQ(missing.errors.size(), 1u);
    EXPECT_EQ(missing.errors[0].key, "line.units[1].profile");
    EXPECT_NE(missing.errors[0].message.find("missing.json"), std::string::npos);
    EXPECT_TRUE(missing.configs.empty());
    // No list: the profile alone.
    const LineProfiles alone =
        loadLineProfiles(defaultMachineConfig(protocol::Variant::Gve64), millPath);
    ASSERT_EQ(alone.configs.size(), 1u);
}
