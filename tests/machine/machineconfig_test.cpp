#include "machine/machineconfig.h"

#include "machine/homing.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>

using namespace frezka;
using namespace frezka::machine;

namespace {

bool hasError(const ConfigResult &r, ConfigErrorCode code, const std::string &key)
{
    for (const ConfigError &e : r.errors) {
        if (e.code == code && e.key == key)
            return true;
    }
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

TEST(MachineConfig, ShippedProfilesLoadAndMatchTheDefaults)
{
    const std::pair<const char *, protocol::Variant> shipped[] = {
        {"gve84", protocol::Variant::Gve84},
        {"gve64", protocol::Variant::Gve64},
        {"gve114", protocol::Variant::Gve114}};
    for (const auto &[name, variant] : shipped) {
        const std::string path =
            std::string(FREZKA_SOURCE_DIR) + "/resources/machines/" + name + ".json";
        const ConfigResult r = loadMachineConfig(path);
        ASSERT_TRUE(r.config.has_value()) << path << "\n" << errorsText(r);
        EXPECT_EQ(*r.config, defaultMachineConfig(variant)) << name;
        EXPECT_TRUE(validateMachineConfig(*r.config).empty()) << name;
    }
}

TEST(MachineConfig, SaveThenLoadGivesTheSameConfig)
{
    QTemporaryDir dir;
    MachineConfig c = defaultMachineConfig(protocol::Variant::Gve114);
    c.name = "Big \"mill\" ü";
    c.axes[3].present = true;
    c.axes[0].stepsPerMm = 320.5;
    c.axes[1].invertDirection = true;
    c.eeprom.interruptEnable = 0xC7;
    c.motion.speedMode = SpeedModeChoice::Vn;
    const std::string path = dir.filePath("m.json").toStdString();
    ASSERT_FALSE(saveMachineConfig(c, path).has_value());
    const ConfigResult r = loadMachineConfig(path);
    ASSERT_TRUE(r.config.has_value()) << errorsText(r);
    EXPECT_EQ(*r.config, c);
}

TEST(MachineConfig, MissingKeysTakeTheVariantDefaults)
{
    const ConfigResult r = parseMachineConfig(R"({"unit": {"variant": "gve84"}})");
    ASSERT_TRUE(r.config.has_value()) << errorsText(r);
    EXPECT_EQ(*r.config, defaultMachineConfig(protocol::Variant::Gve84));
    EXPECT_FALSE(r.config->axes[3].present);
}

TEST(MachineConfig, SyntaxErrorNamesLineAndColumn)
{
    const ConfigResult r = parseMachineConfig("{\n  \"name\": \"x\",\n  \"unit\": {,}\n}");
    ASSERT_FALSE(r.config.has_value());
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].code, ConfigErrorCode::Syntax);
    EXPECT_NE(r.errors[0].message.find("line 3"), std::string::npos) << r.errors[0].message;
}

TEST(MachineConfig, EveryErrorIsReportedWithItsKey)
{
    const ConfigResult r = parseMachineConfig(R"({
        "axes": {"x": {"stepsPerMm": 0, "present": "yes", "stepsPerMM": 3}},
        "motion": {"pauseMs": 30, "speedMode": "fast"},
        "eeprom": {"polarity": "0x1FF"},
        "colour": "red"
    })");
    EXPECT_FALSE(r.config.has_value());
    EXPECT_TRUE(hasError(r, ConfigErrorCode::OutOfRange, "axes.x.stepsPerMm")) << errorsText(r);
    EXPECT_TRUE(hasError(r, ConfigErrorCode::WrongType, "axes.x.present"));
    EXPECT_TRUE(hasError(r, ConfigErrorCode::UnknownKey, "axes.x.stepsPerMM"));
    EXPECT_TRUE(hasError(r, ConfigErrorCode::OutOfRange, "motion.pauseMs"));
    EXPECT_TRUE(hasError(r, ConfigErrorCode::BadChoice, "motion.speedMode"));
    EXPECT_TRUE(hasError(r, ConfigErrorCode::OutOfRange, "eeprom.polarity"));
    EXPECT_TRUE(hasError(r, ConfigErrorCode::UnknownKey, "colour"));
    EXPECT_EQ(r.errors.size(), 7u) << errorsText(r);
    for (const ConfigError &e : r.errors)
        EXPECT_EQ(e.message.rfind(e.key + ": ", 0), 0u) << e.message;
}

TEST(MachineConfig, RangeMessageSaysTheRange)
{
    const ConfigResult r = parseMachineConfig(R"({"motion": {"pauseMs": 30}})");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].message, "motion.pauseMs: is 30, must be 1 .. 24 ms");
}

TEST(MachineConfig, SpeedBeyondThePulseRateIsInconsistent)
{
    // 200 steps/mm at 50 000 pulses/s allow 15 000 mm/min.
    const ConfigResult r = parseMachineConfig(
        R"({"axes": {"x": {"maxSpeedMmPerMin": 15001, "rapidMmPerMin": 15001}}})");
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "axes.x.maxSpeedMmPerMin"))
        << errorsText(r);
    EXPECT_NE(errorsText(r).find("at most 15000 mm/min"), std::string::npos) << errorsText(r);
    const ConfigResult ok = parseMachineConfig(
        R"({"axes": {"x": {"maxSpeedMmPerMin": 15000, "rapidMmPerMin": 15000}}})");
    EXPECT_TRUE(ok.config.has_value()) << errorsText(ok);
}

TEST(MachineConfig, VariantRulesAreChecked)
{
    const ConfigResult r = parseMachineConfig(R"({
        "unit": {"variant": "gve84", "maxPulseRate": 125000},
        "link": {"baud": 57600},
        "axes": {"a": {"present": true}, "x": {"softMinMm": 10, "softMaxMm": 10}},
        "outputs": {"out2": "coolant"},
        "eeprom": {"mpg": "on"}
    })");
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "unit.maxPulseRate")) << errorsText(r);
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "link.baud"));
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "axes.a.present"));
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "axes.x.softMaxMm"));
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "outputs.out2"));
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "eeprom.mpg"));
}

TEST(MachineConfig, TheToolSensorIsInsideTheTravel)
{
    // GVE64 defaults: X 0..400, Z -120..0.
    const ConfigResult r = parseMachineConfig(R"({"tools": {"sensor": {
        "enabled": true, "xMm": 450, "yMm": 10, "clearanceZMm": -100, "travelMm": 30,
        "feedMmPerMin": 100, "slowFeedMmPerMin": 200}}})");
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "tools.sensor.xMm")) << errorsText(r);
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "tools.sensor.travelMm"));
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "tools.sensor.slowFeedMmPerMin"));
    EXPECT_EQ(r.errors.size(), 3u) << errorsText(r);
    // Not checked while the sensor is not there; in range once it fits.
    EXPECT_TRUE(parseMachineConfig(R"({"tools": {"sensor": {"xMm": 450}}})").config);
    const ConfigResult ok = parseMachineConfig(R"({"tools": {"sensor": {
        "enabled": true, "xMm": 390, "yMm": 10, "clearanceZMm": -5, "travelMm": 40,
        "referenceZMm": -30}}})");
    ASSERT_TRUE(ok.config) << errorsText(ok);
    EXPECT_EQ(ok.config->tools.sensor.referenceZMm, -30);
}

TEST(MachineConfig, OldGve64FirmwareHasNoVk)
{
    const ConfigResult r =
        parseMachineConfig(R"({"unit": {"firmwareVersion": 18}, "motion": {"speedMode": "vk"}})");
    EXPECT_TRUE(hasError(r, ConfigErrorCode::Inconsistent, "motion.speedMode")) << errorsText(r);
}

TEST(MachineConfig, ValidateChecksConfigsBuiltInCode)
{
    MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    EXPECT_TRUE(validateMachineConfig(c).empty());
    c.axes[1].accelMmPerS2 = 0;
    const auto errors = validateMachineConfig(c);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].key, "axes.y.accelMmPerS2");
}

TEST(MachineConfig, UnreadableFileIsAnError)
{
    const ConfigResult r = loadMachineConfig("/nonexistent/profile.json");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].code, ConfigErrorCode::FileUnreadable);
    EXPECT_NE(r.errors[0].message.find("/nonexistent/profile.json"), std::string::npos);
}

TEST(MachineConfig, OutputBitsFollowPortZero)
{
    MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    EXPECT_EQ(outputBit(c, OutputFunction::Coolant), 0x04); // OUT1 = bit2
    EXPECT_EQ(outputBit(c, OutputFunction::AirBlow), 0x08); // OUT2 = bit3
    EXPECT_EQ(outputBit(c, OutputFunction::Brake), 0x02);   // OUT3 = bit1
    EXPECT_EQ(outputBit(c, OutputFunction::Laser), 0x00);
    const MachineConfig g84 = defaultMachineConfig(protocol::Variant::Gve84);
    EXPECT_EQ(outputBit(g84, OutputFunction::Spindle), 0x01);
    EXPECT_EQ(outputBit(g84, OutputFunction::Coolant), 0x00);
}

// The outputs by number: which OUTn carries a function, and OUTn's bit of port 0.
TEST(MachineConfig, OutputNumbersAndTheirPortBits)
{
    const MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    EXPECT_EQ(outputNumber(c, OutputFunction::Coolant), 1);
    EXPECT_EQ(outputNumber(c, OutputFunction::AirBlow), 2);
    EXPECT_EQ(outputNumber(c, OutputFunction::Brake), 3);
    EXPECT_EQ(outputNumber(c, OutputFunction::Laser), -1);
    EXPECT_EQ(outputNumber(c, OutputFunction::Unused), -1);
    using protocol::Variant;
    const std::uint8_t bits[4] = {0x01, 0x04, 0x08, 0x02};
    for (int n = 0; n < 4; ++n)
        EXPECT_EQ(outputPortBit(Variant::Gve64, n), bits[n]) << "OUT" << n;
    EXPECT_EQ(outputPortBit(Variant::Gve64, 4), 0);
    EXPECT_EQ(outputPortBit(Variant::Gve64, -1), 0);
    const MachineConfig g84 = defaultMachineConfig(Variant::Gve84);
    EXPECT_EQ(outputNumber(g84, OutputFunction::Spindle), 0); // its relay
    EXPECT_EQ(outputPortBit(Variant::Gve84, 0), 0x01);
    EXPECT_EQ(outputPortBit(Variant::Gve84, 1), 0); // a GVE84 has its relay only
}

TEST(MachineConfig, EepromImageCarriesAxisSettings)
{
    MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    c.axes[0].stepsPerMm = 250;
    c.axes[1].invertDirection = true;
    const auto entries = eepromEntries(c);
    auto find = [&](int addr) {
        for (const EepromEntry &e : entries) {
            if (e.address == addr)
                return e;
        }
        return EepromEntry{0xEE, EepromKind::Byte, -1, "missing"};
    };
    EXPECT_EQ(find(0x30).value, 250);
    EXPECT_EQ(find(0x30).kind, EepromKind::Float);
    EXPECT_EQ(find(0x05).value, 0xFD); // DIR Y inverted: bit1 cleared
    EXPECT_EQ(find(0x01).value, 0x02); // OUT1 coolant
    EXPECT_EQ(find(0x06).value, 0x01); // MPG on
    EXPECT_EQ(find(0x58).value, 10);   // Z homed toward its switch at 10 mm/s
    const MachineConfig g114 = defaultMachineConfig(protocol::Variant::Gve114);
    EXPECT_EQ(eepromEntries(g114).back().address, 0xFD);
    const auto e84 = eepromEntries(defaultMachineConfig(protocol::Variant::Gve84));
    EXPECT_EQ(e84.size(), 3u);
}

TEST(MachineConfig, HomingSequenceInStepsAndPulses)
{
    MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    c.axes[1].homing.homePositionMm = 300;
    c.axes[1].homing.direction = 1;
    const auto seq = homingSequence(c);
    ASSERT_EQ(seq.size(), 3u); // Z first, then X and Y together; A absent
    EXPECT_EQ(seq[0].axis, Axis::Z);
    EXPECT_EQ(seq[0].travelSteps, 140 * 200);
    EXPECT_EQ(seq[1].axis, Axis::X);
    EXPECT_EQ(seq[1].travelSteps, -420 * 200);
    EXPECT_EQ(seq[1].towardPulsesPerS, 2000); // 10 mm/s
    EXPECT_EQ(seq[1].offPulsesPerS, 200);     // 1 mm/s
    EXPECT_EQ(seq[1].backOffSteps, 2000);     // 10 mm
    EXPECT_EQ(seq[2].axis, Axis::Y);
    EXPECT_EQ(seq[2].order, 2);
    EXPECT_EQ(seq[2].homeSteps, 60000);
}

namespace {

double eepromValue(const MachineConfig &c, int address)
{
    for (const EepromEntry &e : eepromEntries(c)) {
        if (e.address == address)
            return e.value;
    }
    return -1;
}

} // namespace

// STEP polarity is set by the physical edge; the byte differs per variant (docs/gve-protocol.md
// §12): GVE64 bit4 set = falling, GVE114 bits 0-3 set = rising (its example 0xAC).
TEST(MachineConfig, StepEdgeIsMappedPerVariant)
{
    MachineConfig g64 = defaultMachineConfig(protocol::Variant::Gve64);
    EXPECT_EQ(eepromValue(g64, 0x05), 0xFF);
    g64.eeprom.stepEdge = StepEdge::Falling;
    EXPECT_EQ(eepromValue(g64, 0x05), 0xFF);
    g64.eeprom.stepEdge = StepEdge::Rising;
    EXPECT_EQ(eepromValue(g64, 0x05), 0xEF);
    MachineConfig g114 = defaultMachineConfig(protocol::Variant::Gve114);
    g114.eeprom.stepEdge = StepEdge::Rising;
    EXPECT_EQ(eepromValue(g114, 0x05), 0xFF);
    g114.eeprom.stepEdge = StepEdge::Falling;
    EXPECT_EQ(eepromValue(g114, 0x05), 0xF0);
    MachineConfig g84 = defaultMachineConfig(protocol::Variant::Gve84);
    g84.eeprom.stepEdge = StepEdge::Rising;
    EXPECT_EQ(eepromValue(g84, 0x05), 0xEF);
}

// The retired stepPolarityInvert meant opposite edges on a GVE64 and a GVE114: an old profile
// keeps the edge it selected, and a note says so; packetCommands is ignored with a note.
TEST(MachineConfig, RetiredKeysAreReadIntoTheirSuccessorsWithANote)
{
    const ConfigResult g64 = parseMachineConfig(
        R"({"link": {"packetCommands": 10}, "eeprom": {"stepPolarityInvert": true}})");
    ASSERT_TRUE(g64.config) << errorsText(g64);
    EXPECT_EQ(g64.config->eeprom.stepEdge, StepEdge::Rising);
    EXPECT_EQ(eepromValue(*g64.config, 0x05), 0xEF); // the byte the old key wrote
    ASSERT_EQ(g64.notes.size(), 2u);
    EXPECT_EQ(g64.notes[0].code, ConfigErrorCode::Retired);
    EXPECT_EQ(g64.notes[0].key, "link.packetCommands");
    EXPECT_NE(g64.notes[1].message.find("\"rising\""), std::string::npos) << g64.notes[1].message;
    const ConfigResult g114 = parseMachineConfig(
        R"({"unit": {"variant": "gve114"}, "eeprom": {"stepPolarityInvert": true}})");
    ASSERT_TRUE(g114.config) << errorsText(g114);
    EXPECT_EQ(g114.config->eeprom.stepEdge, StepEdge::Falling);
    const ConfigResult off = parseMachineConfig(R"({"eeprom": {"stepPolarityInvert": false}})");
    ASSERT_TRUE(off.config);
    EXPECT_EQ(off.config->eeprom.stepEdge, StepEdge::UnitDefault);
    const ConfigResult fresh = parseMachineConfig(R"({"eeprom": {"stepActiveEdge": "rising"}})");
    ASSERT_TRUE(fresh.config) << errorsText(fresh);
    EXPECT_TRUE(fresh.notes.empty());
    EXPECT_EQ(fresh.config->eeprom.stepEdge, StepEdge::Rising);
}

// The PHANTOM's STEP is fixed to the falling edge (GVE64 manual §14.2); W needs IP64MPG v10.
TEST(MachineConfig, FirmwareAndVariantLimitsAreRefused)
{
    const ConfigResult phantom = parseMachineConfig(
        R"({"unit": {"variant": "gve64-phantom"}, "eeprom": {"stepActiveEdge": "rising"}})");
    EXPECT_TRUE(hasError(phantom, ConfigErrorCode::Inconsistent, "eeprom.stepActiveEdge"))
        << errorsText(phantom);
    const ConfigResult falling = parseMachineConfig(
        R"({"unit": {"variant": "gve64-phantom"}, "eeprom": {"stepActiveEdge": "falling"}})");
    EXPECT_TRUE(falling.config) << errorsText(falling);
    const ConfigResult v9 =
        parseMachineConfig(R"({"unit": {"firmwareVersion": 9}, "eeprom": {"mpg": "off"}})");
    EXPECT_TRUE(hasError(v9, ConfigErrorCode::Inconsistent, "axes.z.homing.order"))
        << errorsText(v9);
    const ConfigResult v9NoHoming = parseMachineConfig(R"({"unit": {"firmwareVersion": 9},
        "eeprom": {"mpg": "off"}, "axes": {"x": {"homing": {"order": 0}},
        "y": {"homing": {"order": 0}}, "z": {"homing": {"order": 0}}}})");
    EXPECT_TRUE(v9NoHoming.config) << errorsText(v9NoHoming);
}

// Above 115 200 Bd a GVE114 needs EEPROM 0x0D = 01, below it FF; the image carries it so that
// the connect's EEPROM check finds a unit set for the other range.
TEST(MachineConfig, Gve114BaudRangeIsInTheEepromImage)
{
    MachineConfig c = defaultMachineConfig(protocol::Variant::Gve114);
    c.link.baud = 921600;
    EXPECT_EQ(eepromValue(c, 0x0D), 0x01);
    c.link.baud = 57600;
    EXPECT_EQ(eepromValue(c, 0x0D), 0xFF);
    c.link.baud = 115200; // in both ranges: left as the unit has it
    EXPECT_EQ(eepromValue(c, 0x0D), -1);
    EXPECT_EQ(eepromValue(defaultMachineConfig(protocol::Variant::Gve64), 0x0D), -1);
}

// unit.address: the unit's address on a shared line (GVE114 only), read, written, range-checked.
TEST(MachineConfig, UnitAddressIsReadWrittenAndChecked)
{
    const ConfigResult r = parseMachineConfig(
        R"({"unit": {"variant": "gve114", "maxPulseRate": 125000, "address": 3}})");
    ASSERT_TRUE(r.config.has_value()) << errorsText(r);
    EXPECT_EQ(r.config->unit.address, 3);
    QTemporaryDir dir;
    const std::string path = dir.filePath("m.json").toStdString();
    ASSERT_FALSE(saveMachineConfig(*r.config, path).has_value());
    const ConfigResult back = loadMachineConfig(path);
    ASSERT_TRUE(back.config.has_value()) << errorsText(back);
    EXPECT_EQ(back.config->unit.address, 3);
    const ConfigResult far = parseMachineConfig(R"({"unit": {"variant": "gve114", "address": 7}})");
    ASSERT_FALSE(far.errors.empty());
    EXPECT_NE(errorsText(far).find("unit.address: is 7, must be 0 .. 6"), std::string::npos)
        << errorsText(far);
    const ConfigResult gve64 = parseMachineConfig(R"({"unit": {"address": 1}})");
    EXPECT_TRUE(hasError(gve64, ConfigErrorCode::Inconsistent, "unit.address"))
        << errorsText(gve64);
}
