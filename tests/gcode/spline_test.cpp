// Splines G5, G5.1 and G5.2/G5.3: the chords Frezka cuts lie on the curve and stay within the
// tolerance of it, checked against closed forms (a parabola, a cubic, a circle) and against an
// independent evaluation (LinuxCNC's own Cox-de Boor basis, nurbs_additional_functions.cc),
// plus LinuxCNC's rules and errors and the comparison with rs274's canonical calls.
#include "rs274.h"

#include "gcode/interpreter.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>

#include <cmath>
#include <fstream>

using namespace frezka::gcode;

namespace {

struct Cp
{
    double x, y, w;
};

// LinuxCNC's knot_vector_creator, Nmix and nurbs_point, transcribed (the reference).
double nmix(unsigned i, unsigned k, double u, const std::vector<double> &t)
{
    if (k == 1)
        return (u >= t[i] && u <= t[i + 1]) ? 1 : 0;
    const double a = t[i + k - 1] - t[i], b = t[i + k] - t[i + 1];
    double r = 0;
    if (a != 0)
        r += (u - t[i]) * nmix(i, k - 1, u, t) / a;
    if (b != 0)
        r += (t[i + k] - u) * nmix(i + 1, k - 1, u, t) / b;
    return r;
}

std::array<double, 2> reference(const std::vector<Cp> &cp, unsigned k, double u)
{
    const unsigned n = unsigned(cp.size()) - 1;
    std::vector<double> t;
    for (unsigned i = 0; i <= n + k; ++i)
        t.push_back(i < k ? 0 : i <= n ? double(i - k + 1) : double(n - k + 2));
    double x = 0, y = 0, d = 0;
    for (unsigned i = 0; i <= n; ++i) {
        const double b = nmix(i, k, u, t) * cp[i].w;
        x += cp[i].x * b;
        y += cp[i].y * b;
        d += b;
    }
    return {x / d, y / d};
}

double segmentDistance(double px, double py, double ax, double ay, double bx, double by)
{
    const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / l2, 0.0, 1.0) : 0;
    return std::hypot(px - ax - t * dx, py - ay - t * dy);
}

// Entries [first, first + count) of tp, from tp.start(first), against the reference curve: the
// same line and feed moves, every vertex on the curve (within 1e-6 of a dense polyline of it),
// every point of the curve within tol of the chords, the end exactly the last control point.
void expectFollows(const Toolpath &tp, std::size_t first, std::size_t count,
                   const std::vector<Cp> &cp, unsigned k, double tol)
{
    ASSERT_GE(count, 1u);
    const unsigned n = unsigned(cp.size()) - 1;
    const double uMax = n - k + 2;
    std::vector<std::array<double, 2>> dense;
    const int samples = 20000;
    for (int s = 0; s <= samples; ++s)
        dense.push_back(reference(cp, k, uMax * s / samples));
    std::vector<std::array<double, 2>> ours{{tp.start(first).x, tp.start(first).y}};
    for (std::size_t i = first; i < first + count; ++i) {
        ASSERT_EQ(tp.kind(i), MotionKind::Feed) << i;
        ASSERT_EQ(tp.line(i), tp.line(first)) << i;
        ours.push_back({tp.end(i).x, tp.end(i).y});
    }
    EXPECT_NEAR(ours.front()[0], cp.front().x, 1e-9);
    EXPECT_NEAR(ours.front()[1], cp.front().y, 1e-9);
    EXPECT_EQ(ours.back()[0], cp.back().x);
    EXPECT_EQ(ours.back()[1], cp.back().y);
    for (const auto &v : ours) {
        double best = 1e9;
        for (std::size_t s = 1; s < dense.size(); ++s)
            best = std::min(best, segmentDistance(v[0], v[1], dense[s - 1][0], dense[s - 1][1],
                                                  dense[s][0], dense[s][1]));
        EXPECT_LT(best, 1e-6) << "vertex " << v[0] << " " << v[1] << " is off the curve";
    }
    double worst = 0;
    for (const auto &p : dense) {
        double best = 1e9;
        for (std::size_t s = 1; s < ours.size(); ++s)
            best = std::min(best, segmentDistance(p[0], p[1], ours[s - 1][0], ours[s - 1][1],
                                                  ours[s][0], ours[s][1]));
        worst = std::max(worst, best);
    }
    EXPECT_LE(worst, tol + 1e-9);
    EXPECT_GT(worst, 0.0); // a curve, not a straight line
}

// The feed moves of one source line, from the first at or after `from`.
std::pair<std::size_t, std::size_t> runOf(const Toolpath &tp, std::uint32_t line)
{
    std::size_t first = tp.size(), count = 0;
    for (std::size_t i = 0; i < tp.size(); ++i) {
        if (tp.line(i) == line && tp.kind(i) == MotionKind::Feed) {
            first = std::min(first, i);
            ++count;
        }
    }
    return {first, count};
}

Result run(const std::string &text, Options options = {})
{
    return interpretText(text, options);
}

void expectError(const std::string &text, ErrorCode code, std::uint32_t line, std::uint32_t column)
{
    const Result r = run(text);
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_EQ(r.errors[0].code, code) << text << "\n" << englishMessage(r.errors[0]);
    EXPECT_EQ(r.errors[0].line, line) << text;
    EXPECT_EQ(r.errors[0].column, column) << text;
    EXPECT_FALSE(englishMessage(r.errors[0]).empty());
}

} // namespace

TEST(Spline, QuadraticG51IsAParabola)
{
    // Control points (0,0) (5,10) (10,0): x = 10t, y = 20t(1-t), so y = 2x - x^2/5.
    const Result r = run("G21 G17 G90 F100\nG0 X0 Y0\nG5.1 X10 Y0 I5 J10\nG1 X12\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const auto [first, count] = runOf(r.toolpath, 3);
    ASSERT_GT(count, 20u);
    for (std::size_t i = first; i < first + count; ++i) {
        const Point4 p = r.toolpath.end(i);
        EXPECT_NEAR(p.y, 2 * p.x - p.x * p.x / 5, 1e-9);
        EXPECT_EQ(p.z, 0);
        EXPECT_EQ(r.toolpath.feedMmPerMin(i), 100);
    }
    expectFollows(r.toolpath, first, count, {{0, 0, 1}, {5, 10, 1}, {10, 0, 1}}, 3, 0.002);
    EXPECT_EQ(r.toolpath.end(first + count), (Point4{12, 0, 0, 0})); // G1 X12 from (10, 0)
}

TEST(Spline, CubicG5IsAKnownCubicAndContinuesSmoothlyWithoutIJ)
{
    // Control points (0,0) (4/3,3) (8/3,-3) (4,0): x = 4t, y = 9t(1-t)(1-2t).
    const Result r = run("G21 F200\nG5 X4 Y0 I[4/3] J3 P[-4/3] Q-3\nG5 X8 Y0 P-1 Q1\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const auto [first, count] = runOf(r.toolpath, 2);
    ASSERT_GT(count, 20u);
    for (std::size_t i = first; i < first + count; ++i) {
        const double t = r.toolpath.end(i).x / 4;
        EXPECT_NEAR(r.toolpath.end(i).y, 9 * t * (1 - t) * (1 - 2 * t), 1e-9);
    }
    expectFollows(r.toolpath, first, count,
                  {{0, 0, 1}, {4.0 / 3, 3, 1}, {8.0 / 3, -3, 1}, {4, 0, 1}}, 4, 0.002);
    // The second G5 starts along the first's end tangent: its first control point is the
    // first's second one mirrored through (4, 0), rs274ngc's cycle_i/cycle_j.
    const auto [first2, count2] = runOf(r.toolpath, 3);
    expectFollows(r.toolpath, first2, count2,
                  {{4, 0, 1}, {4 + 4.0 / 3, 3, 1}, {7, 1, 1}, {8, 0, 1}}, 4, 0.002);
}

TEST(Spline, G5WithoutIJAfterAUnitsChangeTakesTheNumbersInTheNewUnits)
{
    // rs274ngc stores the previous G5's -P, -Q as written (cycle_i, cycle_j) and adds them in
    // the units in force: after G20 the 1 of P-1 is an inch.
    const Result r =
        run("G21 F100\nG5 X10 Y0 I1 J1 P-1 Q1\nG20\nG5 X[20/25.4] Y0 P0 Q[-1/25.4]\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const auto [first, count] = runOf(r.toolpath, 4);
    expectFollows(r.toolpath, first, count,
                  {{10, 0, 1}, {10 + 25.4, -25.4, 1}, {20, -1, 1}, {20, 0, 1}}, 4, 0.002);
}

TEST(Spline, NurbsQuarterCircleWithWeights)
{
    // The rational quadratic with weights 1, sqrt(2)/2, 1 over (10,0) (10,10) (0,10) is the
    // quarter circle of radius 10 around the origin.
    const Result r =
        run("G21 F300\nG0 X10 Y0\nG5.2 X10 Y10 P[sqrt[2]/2] L3\nX0 Y10 P1\nG5.3\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const auto [first, count] = runOf(r.toolpath, 5); // the curve is cut at G5.3
    ASSERT_GT(count, 20u);
    for (std::size_t i = first; i < first + count; ++i)
        EXPECT_NEAR(std::hypot(r.toolpath.end(i).x, r.toolpath.end(i).y), 10, 1e-9);
    expectFollows(r.toolpath, first, count, {{10, 0, 1}, {10, 10, std::sqrt(2) / 2}, {0, 10, 1}}, 3,
                  0.002);
    EXPECT_EQ(runOf(r.toolpath, 3).second, 0u); // control point lines do not move
}

TEST(Spline, NurbsOfHigherOrderMatchesLinuxCncsBasis)
{
    const char *prog = "G21 F300\nG0 X1 Y2\nG5.2 P2 L4\nX3 Y7 P1\nX6 Y-2 P0.5\nX9 Y4 P3\n"
                       "X12 Y0 P1\nX15 Y5 P1\nG5.3\nM2\n";
    const Result r = run(prog);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const auto [first, count] = runOf(r.toolpath, 9);
    expectFollows(r.toolpath, first, count,
                  {{1, 2, 2}, {3, 7, 1}, {6, -2, 0.5}, {9, 4, 3}, {12, 0, 1}, {15, 5, 1}}, 4,
                  0.002);
}

TEST(Spline, AHugeCurveHasABoundedNumberOfChords)
{
    // 4 x 2^14 chords at most a knot span, whatever the size and the tolerance.
    Options fine;
    fine.splineToleranceMm = 1e-9;
    const Result r = run("G21 F100\nG5.1 X100000000000 Y0 I50000000000 J100000000000\nM2\n", fine);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_LE(runOf(r.toolpath, 2).second, 4u << 14);
    EXPECT_EQ(r.toolpath.end(r.toolpath.size() - 2).x, 1e11);
}

TEST(Spline, ToleranceIsTheOptionAndInchesAndOffsetsApply)
{
    Options coarse;
    coarse.splineToleranceMm = 0.1;
    const std::string prog = "G21 F100\nG5.1 X10 Y0 I5 J10\nM2\n";
    const Result fine = run(prog), rough = run(prog, coarse);
    ASSERT_TRUE(fine.ok() && rough.ok());
    EXPECT_LT(runOf(rough.toolpath, 2).second, runOf(fine.toolpath, 2).second);
    expectFollows(rough.toolpath, runOf(rough.toolpath, 2).first, runOf(rough.toolpath, 2).second,
                  {{0, 0, 1}, {5, 10, 1}, {10, 0, 1}}, 3, 0.1);

    // G20 words and a work offset: the same curve in mm, moved by the offset; F in in/min.
    const Result inch = run("G10 L2 P1 X100 Y50\nG20\nF4\nG0 X0 Y0 Z1\n"
                            "G5.1 X[10/25.4] Y0 I[5/25.4] J[10/25.4]\nM2\n");
    ASSERT_TRUE(inch.ok()) << englishMessage(inch.errors[0]);
    const auto [first, count] = runOf(inch.toolpath, 5);
    for (std::size_t i = first; i < first + count; ++i) {
        const Point4 p = inch.toolpath.end(i);
        EXPECT_NEAR(p.y - 50, 2 * (p.x - 100) - (p.x - 100) * (p.x - 100) / 5, 1e-9);
        EXPECT_DOUBLE_EQ(p.z, 25.4);
        EXPECT_DOUBLE_EQ(inch.toolpath.feedMmPerMin(i), 4 * 25.4);
    }
    EXPECT_NEAR(inch.toolpath.end(first + count - 1).x, 110, 1e-12);
}

TEST(Spline, ARotatedSystemTurnsTheCurve)
{
    // G10 L2 R90: program (x, y) is machine (-y, x) (+ the system's origin).
    const char *prog = "G10 L2 P1 X5 Y7 R90\nG21 F100\nG0 X0 Y0\nG5.1 X10 Y0 I5 J10\n"
                       "G5.2 X10 Y10 P1\nX0 Y10 P1\nG5.3\nG91 G1 X1\nM2\n";
    const Result r = run(prog);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const auto [first, count] = runOf(r.toolpath, 4);
    ASSERT_GT(count, 20u);
    for (std::size_t i = first; i < first + count; ++i) {
        const Point4 p = r.toolpath.end(i);
        const double x = p.y - 7, y = -(p.x - 5);
        EXPECT_NEAR(y, 2 * x - x * x / 5, 1e-9);
    }
    const auto [nFirst, nCount] = runOf(r.toolpath, 7);
    EXPECT_NEAR(r.toolpath.end(nFirst + nCount - 1).x, 5 - 10, 1e-9);
    EXPECT_NEAR(r.toolpath.end(nFirst + nCount - 1).y, 7 + 0, 1e-9);
    if (!frezka::gcode::test::rs274Path().empty()) { // the G91 move after it starts there
        QTemporaryDir dir;
        const std::string file = dir.filePath("r.ngc").toStdString();
        std::ofstream(file) << prog;
        EXPECT_TRUE(frezka::gcode::test::matchesRs274(file));
    }
}

TEST(Spline, InverseTimeTakesTheWholeSplineInOneOverF)
{
    const Result r = run("G21 G93\nG5.1 X10 Y0 I5 J10 F2\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const auto [first, count] = runOf(r.toolpath, 2);
    double minutes = 0;
    for (std::size_t i = first; i < first + count; ++i) {
        const Point4 a = r.toolpath.start(i), b = r.toolpath.end(i);
        minutes += std::hypot(b.x - a.x, b.y - a.y) / r.toolpath.feedMmPerMin(i);
    }
    EXPECT_NEAR(minutes, 0.5, 1e-9);
}

TEST(Spline, IncrementalNurbsPointsAreFromItsStart)
{
    // rs274ngc keeps the current point at the curve's start until G5.3, so G91 control points
    // are all relative to the start.
    const Result r = run("G21 F100\nG0 X10 Y0\nG91 G5.2 X0 Y10 P1\nX-10 Y10 P1\nG5.3\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const auto [first, count] = runOf(r.toolpath, 5);
    expectFollows(r.toolpath, first, count, {{10, 0, 1}, {10, 10, 1}, {0, 10, 1}}, 3, 0.002);
}

TEST(Spline, LinuxCncsErrorsWithLineAndColumn)
{
    using E = ErrorCode;
    expectError("F100\nG18 G5.1 X1 Y1 I1 J1\nM2\n", E::SplinePlane, 2, 5);
    expectError("F100\nG5.1 X1 Y1 I1\nM2\n", E::SplineMissingWords, 2, 1);
    expectError("F100\nG5 X1 Y1 I1 J1 P1\nM2\n", E::SplineMissingWords, 2, 1);
    expectError("F100\nG5 X1 Y1 J1 P1 Q1\nM2\n", E::SplineMissingWords, 2, 1);
    expectError("F100\nG5.1 X1 Y1 Z2 I1 J1\nM2\n", E::SplineAxisWord, 2, 12);
    expectError("G5.1 X1 Y1 I1 J1\nM2\n", E::ZeroFeedRate, 1, 1);
    expectError("G93\nG5.1 X1 Y1 I1 J1\nM2\n", E::InverseTimeFeedMissing, 2, 1);
    expectError("F100\nG5.1 X1 Y1 I1 J1 P1\nM2\n", E::WordNotUsed, 2, 18);
    expectError("F100 G0 X-5\nG41.1 D1 G1 X0\nG5.1 X1 Y1 I1 J1\nM2\n", E::CompNotAllowed, 3, 1);
    expectError("F100\nG5.3\nM2\n", E::NurbsNotStarted, 2, 1);
    expectError("F100\nG5.2 X1 Y1 P1 L4\nX2 Y0 P1\nG5.3\nM2\n", E::NurbsTooFewPoints, 4, 1);
    expectError("F100\nG5.2 X1 Y1 L3\nM2\n", E::NurbsBadWeight, 2, 6);
    expectError("F100\nG5.2 X1 Y1 P0\nM2\n", E::NurbsBadWeight, 2, 12);
    expectError("F100\nG5.2 X1 Y1 P[1/10000000]\nM2\n", E::NurbsBadWeight, 2, 12);
    expectError("F100\nG5.2 X1 Y1 P2000000\nM2\n", E::NurbsBadWeight, 2, 12);
    expectError("F100\nG5.2 P-1\nX1 Y1 P1\nM2\n", E::NurbsBadWeight, 2, 6);
    expectError("F100\nG5.2 X1 P1\nM2\n", E::NurbsMissingXy, 2, 6);
    expectError("F100\nG5.2 X1 Y1 P1\nP2\nG5.3\nM2\n", E::WordNotUsed, 3, 1);
    expectError("F100\nG5.2 X1 Y1 P1 L2.5\nM2\n", E::NurbsBadOrder, 2, 15);
    expectError("F100\nG5.2 X1 Y1 P1 L11\nM2\n", E::NurbsBadOrder, 2, 15);
    expectError("G93 F1\nG5.2 X1 Y1 P1\nM2\n", E::NurbsInverseTime, 2, 1);
    expectError("F100\nG5.2 X1 Y1 P1\nX2 Y0 P1\nG5.3 G1 X4\nM2\n", E::NurbsOnlyControlPoints, 4, 6);
    expectError("F100\nG5.2 X1 Y1 P1\nX2 Y0 P1\nG5.3 X4\nM2\n", E::WordNotUsed, 4, 6);
    expectError("F100\nG5.2 X1 Y1 P1\nX2 Y0 P1\nG5.3\nX4\nM2\n", E::AxisWordsWithoutMotion, 5, 1);
    expectError("F100\nG19 G5.2 X1 Y1 P1\nM2\n", E::SplinePlane, 2, 5);
    expectError("F100\nG5.2 X1 Y1 Z1 P1\nM2\n", E::SplineAxisWord, 2, 12);
}

TEST(Spline, ANurbsNotEndedByG53IsAnError)
{
    // LinuxCNC drops the curve without cutting it; Frezka refuses the program.
    expectError("F100\nG5.2 X1 Y1 P1\nX2 Y0 P1\nG1 X5\nM2\n", ErrorCode::NurbsNotEnded, 4, 1);
    expectError("F100\nG5.2 X1 Y1 P1\nX2 Y0 P1\nM2\n", ErrorCode::NurbsNotEnded, 4, 1);
    expectError("F100\nG5.2 X1 Y1 P1\nX2 Y0 P1\n", ErrorCode::NurbsNotEnded, 2, 1);
    const Result r = run("F100\nG5.2 X1 Y1 P1\nX2 Y0 P1\n");
    EXPECT_EQ(r.errors[0].detail, "2");
    // A new G5.2 right after G5.3 in the same block starts the next curve.
    const Result next =
        run("F100\nG5.2 X1 Y1 P1\nX2 Y0 P1\nG5.3 G5.2 X3 Y1 P1\nX4 Y0 P1\nG5.3\nM2\n");
    ASSERT_TRUE(next.ok()) << englishMessage(next.errors[0]);
    EXPECT_EQ(next.toolpath.end(next.toolpath.size() - 2), (Point4{4, 0, 0, 0}));
}

TEST(Spline, CheckModeReportsABadCurveOnce)
{
    Options check;
    check.collectAllErrors = true;
    const Result notEnded =
        run("F100\nG5.2 X1 Y1 P1\nX2 Y0 P1\nG1 X5\nG1 X6\nG0 X7\nG2 X8 R1\nM2\n", check);
    ASSERT_EQ(notEnded.errors.size(), 1u) << englishMessage(notEnded.errors.back());
    EXPECT_EQ(notEnded.errors[0].code, ErrorCode::NurbsNotEnded);
    EXPECT_EQ(notEnded.errors[0].line, 4u);
    const Result tooFew =
        run("F100\nG5.2 X1 Y1 P1 L4\nX2 Y0 P1\nG5.3\nG1 X5\nX6\nG5.3\nM2\n", check);
    ASSERT_EQ(tooFew.errors.size(), 2u) << englishMessage(tooFew.errors.back());
    EXPECT_EQ(tooFew.errors[0].code, ErrorCode::NurbsTooFewPoints);
    EXPECT_EQ(tooFew.errors[1].code, ErrorCode::NurbsNotStarted); // line 7, a real one
    EXPECT_EQ(tooFew.errors[1].line, 7u);
}

TEST(Spline, SameMotionsAsRs274)
{
    if (frezka::gcode::test::rs274Path().empty())
        GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
    QTemporaryDir dir;
    const std::string file = dir.filePath("s.ngc").toStdString();
    // Each spline is followed by an incremental move: rs274 prints that move's end, which
    // checks where the spline ended (NURBS_FEED prints no coordinates).
    std::ofstream(file) << "G21 G17 G90 F100\nG0 X1 Y2\nG5.1 X10 Y0 I5 J10\nG91 G1 X1 Y1\n"
                           "G90 F250\nG5 X20 Y5 I2 J2 P-1 Q3\nG5 X25 Y0 P1 Q2\nG91 G0 X1\n"
                           "G90 G0 X0 Y0\nG20\nF5\nG5.2 X1 Y0 P1 L3\nX1 Y1 P0.5\nX0 Y1 P1\n"
                           "G5.3\nG91 G1 X0.5\nG21 G5.1 X5 Y5 I0 J5\nG1 Y1\nG90 G0 X0\nM2\n";
    EXPECT_TRUE(frezka::gcode::test::matchesRs274(file));
}

TEST(Spline, LinuxCncsButterflyMatchesRs274)
{
    if (frezka::gcode::test::rs274Path().empty())
        GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
    EXPECT_TRUE(frezka::gcode::test::matchesRs274(std::string(FREZKA_GCODE_DATA_DIR) +
                                                  "/spline/butterfly.nc"));
}
