#pragma once
// The spiral of bench_gui_load (tests/bench/gui): an N-line program of short G1 segments, like
// CAM output for a 3D surface, inside the default profile's travel (X 70..330, Y 20..280,
// Z -1 mm). Written to `path`; false when it cannot be.

#include <QByteArray>
#include <QFile>
#include <QString>

#include <cmath>

namespace frezka::gui::test {

inline bool writeSpiral(const QString &path, long lines)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return false;
    QByteArray buf;
    buf.reserve(1 << 20);
    buf += "G21 G90 G94\nG0 X0 Y0 Z0\nG1 Z-1 F1500\n";
    for (long i = 3; i < lines - 1; ++i) {
        const double t = double(i) * 0.002;
        const double r = 10 + double(i) * 120.0 / double(lines);
        buf += "G1 X" + QByteArray::number(200 + r * std::cos(t), 'f', 3) + " Y" +
               QByteArray::number(150 + r * std::sin(t), 'f', 3) + "\n";
        if (buf.size() > (1 << 20) - 64) {
            if (f.write(buf) != buf.size())
                return false;
            buf.clear();
        }
    }
    buf += "M30\n";
    return f.write(buf) == buf.size();
}

} // namespace frezka::gui::test
