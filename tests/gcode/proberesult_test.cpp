// Programs that probe for themselves (issue 19): the interpreter given the results of the probe
// moves already run (Options::probeResults) goes on from where each stopped, and marks where the
// path starts to depend on a probe that has not run yet (Result::provisionalEntry/Line).
#include "gcode/interpreter.h"

#include <gtest/gtest.h>

using namespace frezka::gcode;

namespace {

// G38.2 down, the work's top made Z0 of G54, then a cut 0.1 below it.
constexpr const char *kTouchOff = "G21 G90 G54\n"          // 1
                                  "G0 X10 Y20 Z0\n"        // 2
                                  "G38.2 Z-10 F50\n"       // 3
                                  "G10 L20 P1 Z0\n"        // 4
                                  "G0 Z1\n"                // 5
                                  "G1 Z-0.1 F100\n"        // 6
                                  "#100 = #5063\n"         // 7
                                  "#101 = #5070\n"         // 8
                                  "G1 X[#100 * 10 + 10]\n" // 9: X carries #5063 (program Z)
                                  "M2\n";

Result run(const char *text, std::vector<ProbeResult> results = {})
{
    Options o;
    o.probeResults = std::move(results);
    Interpreter interp(o);
    Result r = interp.run(text);
    EXPECT_TRUE(r.errors.empty()) << (r.errors.empty() ? "" : errorName(r.errors.front().code));
    return r;
}

std::size_t entryOfLine(const Toolpath &t, std::uint32_t line)
{
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t.line(i) == line)
            return i;
    ADD_FAILURE() << "no entry on line " << line;
    return 0;
}

} // namespace

TEST(ProbeResult, WithoutResultTheProbeEndsAtItsProgrammedEndAndIsProvisional)
{
    const Result r = run(kTouchOff);
    const Toolpath &t = r.toolpath;
    const std::size_t probe = entryOfLine(t, 3);
    EXPECT_EQ(t.kind(probe), MotionKind::Probe);
    EXPECT_EQ(t.end(probe).z, -10);
    EXPECT_EQ(r.provisionalEntry, probe);
    EXPECT_EQ(r.provisionalLine, 3u);
    EXPECT_EQ(r.probes, 1u);
    // The work zero at the programmed depth: the cut at -10.1 in machine Z.
    EXPECT_DOUBLE_EQ(t.end(entryOfLine(t, 6)).z, -10.1);
}

TEST(ProbeResult, TheTripPointIsTheProbesEndAndItsParameters)
{
    // The probe touched at Z -3.2 (machine): the next move starts there, G10 L20 makes it Z0.
    const Result r = run(kTouchOff, {{{10, 20, -3.2, 0}, true}});
    const Toolpath &t = r.toolpath;
    const std::size_t probe = entryOfLine(t, 3);
    EXPECT_EQ(t.end(probe).z, -3.2);
    EXPECT_EQ(r.provisionalEntry, Result::kNoEntry);
    EXPECT_EQ(r.provisionalLine, 0u);
    EXPECT_EQ(r.probes, 1u);
    EXPECT_EQ(t.start(probe + 1).z, -3.2);
    EXPECT_DOUBLE_EQ(t.end(entryOfLine(t, 5)).z, -2.2);
    EXPECT_NEAR(t.end(entryOfLine(t, 6)).z, -3.3, 1e-12);
    // #5063 in program coordinates before the G10 (G54 was 0 then): -3.2 -> X = -22.
    EXPECT_NEAR(t.end(entryOfLine(t, 9)).x, -22, 1e-12);
}

TEST(ProbeResult, TheOffsetsTheProgramSetsComeOutForTheCallerToKeep)
{
    // With the trip point: G54's Z is where it tripped; the other systems as they came in.
    const Result tripped = run(kTouchOff, {{{10, 20, -3.2, 0}, true}});
    EXPECT_TRUE(tripped.workOffsetsChanged);
    EXPECT_EQ(tripped.workOffsetsMm[0], (std::array<double, 4>{0, 0, -3.2, 0}));
    EXPECT_EQ(tripped.workOffsetsMm[1], (std::array<double, 4>{}));
    // Provisional: the programmed end; the session takes the last re-interpretation's.
    EXPECT_EQ(run(kTouchOff).workOffsetsMm[0][2], -10);
    // A program without G10 L2/L20 leaves them as given, and says so.
    Options o;
    o.workOffsetsMm[2] = {1, 2, 3, 4};
    Interpreter interp(o);
    const Result plain = interp.run("G21 G90 G56\nG0 X1\nM2\n");
    EXPECT_FALSE(plain.workOffsetsChanged);
    EXPECT_EQ(plain.workOffsetsMm, o.workOffsetsMm);
}

TEST(ProbeResult, ProbeSuccessParameterFollowsTheResult)
{
    const char *text = "G21 G90\nG38.3 Z-5 F50\n#1 = #5070\nG0 X[#1 * 7]\nM2\n";
    EXPECT_EQ(run(text).toolpath.end(entryOfLine(run(text).toolpath, 4)).x, 7); // assumed
    const Result missed = run(text, {{{0, 0, -5, 0}, false}});
    EXPECT_EQ(missed.toolpath.end(entryOfLine(missed.toolpath, 4)).x, 0);
    const Result hit = run(text, {{{0, 0, -1.5, 0}, true}});
    EXPECT_EQ(hit.toolpath.end(entryOfLine(hit.toolpath, 4)).x, 7);
}

TEST(ProbeResult, ProbesAreCountedInTheOrderTheyRunAndTheFirstWithoutResultIsProvisional)
{
    // Three probes from a loop (one line, three runs): results for the first two.
    const char *text = "G21 G90 F60\n"
                       "#1 = 0\n"
                       "o10 while [#1 LT 3]\n"
                       "G0 X[#1 * 10] Z1\n"
                       "G38.2 Z-5\n"
                       "#[500 + #1] = #5063\n"
                       "#1 = [#1 + 1]\n"
                       "o10 endwhile\n"
                       "G0 Z5\n"
                       "G1 X0 Z[#500 + #501 + #502]\n"
                       "M2\n";
    const Result r = run(text, {{{0, 0, -1, 0}, true}, {{10, 0, -2, 0}, true}});
    const Toolpath &t = r.toolpath;
    std::vector<std::size_t> probes;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t.kind(i) == MotionKind::Probe)
            probes.push_back(i);
    ASSERT_EQ(probes.size(), 3u);
    EXPECT_EQ(r.probes, 3u);
    EXPECT_EQ(t.end(probes[0]).z, -1);
    EXPECT_EQ(t.end(probes[1]).z, -2);
    EXPECT_EQ(t.end(probes[2]).z, -5); // programmed: provisional
    EXPECT_EQ(r.provisionalEntry, probes[2]);
    EXPECT_EQ(r.provisionalLine, 5u);
    EXPECT_EQ(t.end(t.size() - 2).z, -8); // -1 - 2 - 5 (the last from the programmed end)
}
