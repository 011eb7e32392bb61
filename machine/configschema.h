#pragma once
// The profile schema, written once: visitProfile() walks every key of a MachineConfig with its
// range and unit, and each visitor (JSON reader, JSON writer, range checker) does its part.
// Internal to frezka_machine.

#include "machine/machineconfig.h"

#include <span>
#include <string>

namespace frezka::machine::schema {

template<class E>
struct Choice
{
    const char *name;
    E value;
};

inline constexpr Choice<SpeedModeChoice> kSpeedModes[] = {
    {"auto", SpeedModeChoice::Auto}, {"vk", SpeedModeChoice::Vk}, {"vn", SpeedModeChoice::Vn}};

inline constexpr Choice<OutputFunction> kOutputFunctions[] = {
    {"unused", OutputFunction::Unused},
    {"spindle", OutputFunction::Spindle},
    {"laser", OutputFunction::Laser},
    {"coolant", OutputFunction::Coolant},
    {"airBlow", OutputFunction::AirBlow},
    {"coverLock", OutputFunction::CoverLock},
    {"toolRelease", OutputFunction::ToolRelease},
    {"toolCoverOpen", OutputFunction::ToolCoverOpen},
    {"brake", OutputFunction::Brake},
    {"interrupt", OutputFunction::Interrupt}};

inline constexpr Choice<MpgMode> kMpgModes[] = {
    {"off", MpgMode::Off},
    {"on", MpgMode::On},
    {"onWithLimits", MpgMode::OnWithLimits},
    {"onRotaryA", MpgMode::OnRotaryA},
    {"onRotaryAWithLimits", MpgMode::OnRotaryAWithLimits}};

inline constexpr Choice<StepEdge> kStepEdges[] = {{"default", StepEdge::UnitDefault},
                                                  {"falling", StepEdge::Falling},
                                                  {"rising", StepEdge::Rising}};

inline constexpr Choice<protocol::Variant> kVariants[] = {
    {"gve84", protocol::Variant::Gve84},
    {"gve64", protocol::Variant::Gve64},
    {"gve64-phantom", protocol::Variant::Gve64Phantom},
    {"gve114", protocol::Variant::Gve114}};

// A dynamic-extent span over a choice table (what the visitors take).
template<class E, std::size_t N>
constexpr std::span<const Choice<E>> all(const Choice<E> (&table)[N])
{
    return std::span<const Choice<E>>(table, N);
}

inline constexpr const char *kAxisKeys[] = {"x", "y", "z", "a"};

// Visitor interface (duck-typed):
//   number(key, double&, min, max, unit)   integer(key, int&, min, max, unit)
//   boolean(key, bool&)   text(key, std::string&)   byte(key, std::uint8_t&)
//   choice(key, E&, span<const Choice<E>>)   object(key, fn(Visitor&))
template<class V>
void visitHoming(V &v, HomingConfig &h)
{
    v.integer("order", h.order, 0, 4, "");
    v.integer("direction", h.direction, -1, 1, "");
    v.number("travelMm", h.travelMm, 0.1, 100000, "mm");
    v.number("towardMmPerS", h.towardMmPerS, 0.01, 1000, "mm/s");
    v.number("offMmPerS", h.offMmPerS, 0.01, 1000, "mm/s");
    v.number("backOffMm", h.backOffMm, 0.01, 1000, "mm");
    v.number("homePositionMm", h.homePositionMm, -100000, 100000, "mm");
}

template<class V>
void visitAxis(V &v, AxisConfig &a)
{
    v.boolean("present", a.present);
    v.number("stepsPerMm", a.stepsPerMm, 1, 10000, "steps/mm");
    v.boolean("invertDirection", a.invertDirection);
    v.number("softMinMm", a.softMinMm, -100000, 100000, "mm");
    v.number("softMaxMm", a.softMaxMm, -100000, 100000, "mm");
    v.number("maxSpeedMmPerMin", a.maxSpeedMmPerMin, 1, 1000000, "mm/min");
    v.number("rapidMmPerMin", a.rapidMmPerMin, 1, 1000000, "mm/min");
    v.number("accelMmPerS2", a.accelMmPerS2, 1, 100000, "mm/s²");
    v.number("maxJumpMmPerS", a.maxJumpMmPerS, 0, 1000, "mm/s");
    v.object("homing", [&](V &s) { visitHoming(s, a.homing); });
}

template<class V>
void visitProfile(V &v, MachineConfig &c)
{
    v.text("name", c.name);
    v.object("unit", [&](V &s) {
        s.choice("variant", c.unit.variant, all(kVariants));
        s.integer("maxPulseRate", c.unit.maxPulseRate, 10, 500000, "pulses/s");
        s.integer("firmwareVersion", c.unit.firmwareVersion, 1, 99, "");
        s.integer("startInput", c.unit.startInput, 0, 7, "");
        s.integer("address", c.unit.address, 0, 6, "");
    });
    v.object("link", [&](V &s) {
        s.text("port", c.link.port);
        s.integer("baud", c.link.baud, 9600, 921600, "Bd");
        s.boolean("checksums", c.link.checksums);
        s.boolean("packets", c.link.packets);
        s.number("latencyMs", c.link.latencyMs, 0, 100, "ms");
    });
    v.object("axes", [&](V &s) {
        for (int i = 0; i < kAxisCount; ++i)
            s.object(kAxisKeys[i], [&](V &t) { visitAxis(t, c.axes[i]); });
    });
    v.object("motion", [&](V &s) {
        s.number("junctionDeviationMm", c.motion.junctionDeviationMm, 0, 10, "mm");
        s.number("chordToleranceMm", c.motion.chordToleranceMm, 0.0001, 1, "mm");
        s.integer("pauseMs", c.motion.pauseMs, 1, 24, "ms");
        s.choice("speedMode", c.motion.speedMode, all(kSpeedModes));
        s.number("toolLiftMm", c.motion.toolLiftMm, 0, 1000, "mm");
        s.boolean("runBeforeHoming", c.motion.runBeforeHoming);
    });
    v.object("spindle", [&](V &s) {
        s.number("maxRpm", c.spindle.maxRpm, 1, 1000000, "rpm");
        s.integer("spinUpMs", c.spindle.spinUpMs, 0, 60000, "ms");
        s.boolean("stopAtProgramStop", c.spindle.stopAtProgramStop);
        s.boolean("stopAtToolChange", c.spindle.stopAtToolChange);
    });
    v.object("outputs", [&](V &s) {
        s.choice("out1", c.outputs.out[0], all(kOutputFunctions));
        s.choice("out2", c.outputs.out[1], all(kOutputFunctions));
        s.choice("out3", c.outputs.out[2], all(kOutputFunctions));
        s.choice("mist", c.outputs.mist, all(kOutputFunctions));
    });
    v.object("eeprom", [&](V &s) {
        EepromConfig &e = c.eeprom;
        s.boolean("sync", e.sync);
        s.choice("mpg", e.mpg, all(kMpgModes));
        s.number("mpgAccelMmPerS2", e.mpgAccelMmPerS2, 1, 10000, "mm/s²");
        s.number("mpgMaxSpeedMmPerS", e.mpgMaxSpeedMmPerS, 0.1, 10000, "mm/s");
        s.integer("mpgDelayMs", e.mpgDelayMs, 1, 2000, "ms");
        s.number("mpgStepMultiplier", e.mpgStepMultiplier, 0.001, 1000, "");
        s.integer("homingInput", e.homingInput, 0, 7, "");
        s.byte("interruptEnable", e.interruptEnable);
        s.byte("interruptEnableHigh", e.interruptEnableHigh);
        s.byte("polarity", e.polarity);
        s.byte("polarityHigh", e.polarityHigh);
        s.integer("aSlavedTo", e.aSlavedTo, 0, 3, "");
        s.boolean("pwmBreakout", e.pwmBreakout);
        s.choice("stepActiveEdge", e.stepEdge, all(kStepEdges));
        s.integer("defaultSpindlePermille", e.defaultSpindlePermille, 1, 1000, "‰");
        s.number("brakeReleaseDelayS", e.brakeReleaseDelayS, 0, 5, "s");
    });
    v.object("tools", [&](V &s) {
        s.text("tableFile", c.tools.tableFile);
        s.object("sensor", [&](V &t) {
            ToolSensorConfig &k = c.tools.sensor;
            t.boolean("enabled", k.enabled);
            t.number("xMm", k.xMm, -100000, 100000, "mm");
            t.number("yMm", k.yMm, -100000, 100000, "mm");
            t.number("clearanceZMm", k.clearanceZMm, -100000, 100000, "mm");
            t.number("travelMm", k.travelMm, 0.1, 1000, "mm");
            t.number("feedMmPerMin", k.feedMmPerMin, 1, 10000, "mm/min");
            t.number("slowFeedMmPerMin", k.slowFeedMmPerMin, 0.1, 10000, "mm/min");
            t.number("retractMm", k.retractMm, 0.1, 100, "mm");
            t.number("referenceZMm", k.referenceZMm, -100000, 100000, "mm");
        });
    });
    v.object("program", [&](V &s) {
        s.integer("maxLinesExecuted", c.program.maxLinesExecuted, 1000, 2'000'000'000, "");
        s.integer("maxMoves", c.program.maxMoves, 1000, 200'000'000, "");
        s.text("subroutinePath", c.program.subroutinePath);
    });
}

} // namespace frezka::machine::schema
