// Randomized differential test against LinuxCNC's rs274: deterministic pseudo-random programs
// mixing straight moves, IJK and R arcs (helical, in all planes, incremental so they are valid
// wherever they start), work offsets, G92, canned cycles with G98/G99 and L repeats, G28/G30,
// dwells, A moves, expressions and inch programs. Each must give the same motions as rs274.
#include "rs274.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>

using namespace frezka::gcode;

namespace {

class ProgramGenerator
{
public:
    explicit ProgramGenerator(unsigned seed)
        : m_rng(seed)
    {}

    std::string program(int blocks)
    {
        const bool inch = pick(5) == 0;
        m_scale = inch ? 0.05 : 1.0;
        m_out << (inch ? "G20" : "G21") << " G90 G17 G94 F" << num(100 + pick(900), 1) << "\n";
        for (int i = 0; i < blocks; ++i)
            block();
        m_out << "G80 G90 G17\nM2\n";
        return m_out.str();
    }

private:
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_rng); }
    double real(double lo, double hi)
    {
        return std::uniform_real_distribution<double>(lo, hi)(m_rng);
    }
    std::string num(double v, double scale = -1)
    {
        std::ostringstream s;
        s.setf(std::ios::fixed);
        s.precision(4);
        s << v * (scale < 0 ? m_scale : scale);
        return s.str();
    }
    std::string pos() { return num(real(-40, 40)); }

    void block()
    {
        switch (pick(20)) {
        case 0:
        case 1:
        case 2:
            m_out << (pick(2) ? "G0" : "G1") << " X" << pos() << " Y" << pos()
                  << (pick(2) ? " Z" + pos() : "") << "\n";
            break;
        case 3:
        case 4:
        case 5:
            arc();
            break;
        case 6:
            m_out << "G10 L2 P" << 1 + pick(3) << " X" << pos() << " Y" << pos() << " Z"
                  << num(real(-5, 5)) << "\nG" << 54 + pick(3) << "\n";
            break;
        case 7:
            m_out << (pick(3) ? "G92 X" + pos() + " Y" + pos() : std::string("G92.1")) << "\n";
            break;
        case 8:
            cycle();
            break;
        case 9:
            m_out << "G0 Z" << num(real(0, 10)) << "\nG28.1\nG0 X" << pos() << "\nG28 Z"
                  << num(real(1, 9)) << "\n";
            break;
        case 10:
            m_out << "G4 P" << num(real(0, 2), 1) << "\nM3 S" << 1000 + pick(20000) << "\n";
            break;
        case 11:
            m_out << "G1 A" << num(real(-90, 90), 1) << " X" << pos() << " F"
                  << num(50 + pick(2000), 1) << "\n";
            break;
        case 12:
            m_out << "#1 = " << num(real(-10, 10)) << "\nG1 X[#1 * 2 + " << num(1)
                  << "] Y[sin[#1] * " << num(10) << "]\n";
            break;
        case 14: // inverse time feed: F on every move
            m_out << "G93 G1 X" << pos() << " Y" << pos() << " F" << num(real(0.5, 20), 1)
                  << "\nG91 G2 X" << num(4) << " Y0 I" << num(2) << " J0 F" << num(real(1, 9), 1)
                  << "\nG90 G94 F" << num(100 + pick(900), 1) << "\n";
            break;
        case 15: { // loops and conditionals
            const int loop = ++m_label, branch = ++m_label;
            m_out << "#2 = " << pick(4) << "\no" << loop << " repeat [#2 + 1]\n"
                  << "  G91 G1 X" << num(real(-3, 3)) << " Y" << num(real(-3, 3)) << "\n  G90\n"
                  << "o" << loop << " endrepeat\no" << branch << " if [#2 GT 1]\n  G0 Z"
                  << num(real(0, 5)) << "\no" << branch << " else\n  G0 Z" << num(real(-5, 0))
                  << "\no" << branch << " endif\n";
            break;
        }
        case 16: // absolute arc centre computed from the current position
            m_out << "G90.1 G91 G3 X" << num(6) << " Y" << num(6) << " I[#<_x> + " << num(3)
                  << "] J[#<_y> + " << num(3) << "]\nG90 G91.1\n";
            break;
        case 17:
            m_out << "G53 G0 X" << pos() << " Z" << num(real(-5, 5)) << "\n";
            break;
        case 18:
            m_out << "G0 X[#5420 + " << num(1) << "] Y[#<_y> - " << num(1) << "]\n";
            break;
        default:
            m_out << "G91 G1 X" << num(real(-5, 5)) << " Y" << num(real(-5, 5)) << "\nG90\n";
            break;
        }
    }

    // Arcs are written in G91: start + centre offset and end offset on the same circle.
    void arc()
    {
        static const char *kPlanes[3][5] = {
            {"G17", "X", "Y", "I", "J"}, {"G18", "Z", "X", "K", "I"}, {"G19", "Y", "Z", "J", "K"}};
        const char *const *p = kPlanes[pick(3)];
        const char *w = p[0][2] == '7' ? "Z" : p[0][2] == '8' ? "Y" : "X";
        const char *g = pick(2) ? "G2" : "G3";
        m_out << p[0] << " G91 " << g;
        if (pick(3)) {
            const double i = real(-10, 10), j = real(-10, 10);
            const double t = real(-3, 3);
            // end = centre + rotated (start - centre), relative to the start
            const double ex = i + (-i * std::cos(t) + j * std::sin(t));
            const double ey = j + (-i * std::sin(t) - j * std::cos(t));
            m_out << " " << p[1] << num(ex) << " " << p[2] << num(ey) << " " << p[3] << num(i)
                  << " " << p[4] << num(j);
            if (pick(4) == 0)
                m_out << " P" << 1 + pick(3);
        } else {
            const double dx = real(-10, 10), dy = real(-10, 10);
            const double r = std::hypot(dx, dy) / 2 * real(1.01, 3) * (pick(2) ? 1 : -1);
            m_out << " " << p[1] << num(dx) << " " << p[2] << num(dy) << " R" << num(r);
        }
        if (pick(2))
            m_out << " " << w << num(real(-2, 2));
        m_out << "\nG90 G17\n";
    }

    void cycle()
    {
        const int cycles[] = {73, 81, 82, 83, 85, 89};
        const int g = cycles[pick(6)];
        const bool incremental = pick(3) == 0;
        // Plane: the two positioning letters and the depth letter.
        static const char *kPlanes[3][4] = {
            {"G17", "X", "Y", "Z"}, {"G18", "Z", "X", "Y"}, {"G19", "Y", "Z", "X"}};
        const char *const *pl = kPlanes[pick(4) == 0 ? 1 + pick(2) : 0];
        m_out << pl[0] << " " << (pick(2) ? "G98" : "G99") << (incremental ? " G91" : " G90")
              << " G" << g;
        if (incremental)
            m_out << " " << pl[1] << num(real(-5, 5)) << " " << pl[2] << num(real(-5, 5)) << " "
                  << pl[3] << num(-real(1, 5)) << " R" << num(real(-2, 2)) << " L" << 1 + pick(3);
        else
            m_out << " " << pl[1] << pos() << " " << pl[2] << pos() << " " << pl[3]
                  << num(-real(1, 5)) << " R" << num(real(0, 3));
        if (g == 82 || g == 89)
            m_out << " P" << num(real(0, 1), 1);
        if (g == 73 || g == 83)
            m_out << " Q" << num(real(0.5, 2));
        m_out << "\n";
        for (int k = pick(3); k > 0; --k)
            m_out << pl[1] << (incremental ? num(real(-5, 5)) : pos()) << "\n";
        m_out << "G80 G90 G17\n";
    }

    std::mt19937 m_rng;
    std::ostringstream m_out;
    double m_scale = 1;
    int m_label = 0;
};

} // namespace

TEST(RandomPrograms, MatchRs274)
{
    if (test::rs274Path().empty())
        GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    // FREZKA_RANDOM_PROGRAMS=N runs more programs (40 by default, ~2 s).
    const char *env = std::getenv("FREZKA_RANDOM_PROGRAMS");
    const unsigned count = env ? static_cast<unsigned>(std::strtoul(env, nullptr, 10)) : 40;
    for (unsigned seed = 1; seed <= count; ++seed) {
        const std::string text = ProgramGenerator(seed).program(120);
        const std::string file =
            dir.filePath(QStringLiteral("random%1.nc").arg(seed)).toStdString();
        std::ofstream(file) << text;
        EXPECT_TRUE(test::matchesRs274(file)) << "seed " << seed << ", program:\n" << text;
    }
}
