#pragma once
// The spiral of bench_gui_load (tests/bench/gui) written to a file: an N-line program of short
// G1 segments, like CAM output for a 3D surface, inside the default profile's travel (X 70..330,
// Y 20..280, Z -1 mm). The lines are tests/machine/spiralprogram.h's, written a megabyte at a
// time (a 5 M-line program is 104 MB). False when the file cannot be written.

#include "../machine/spiralprogram.h"

#include <QByteArray>
#include <QFile>
#include <QString>

namespace frezka::gui::test {

inline bool writeSpiral(const QString &path, long lines)
{
    using namespace frezka::machine::test;
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return false;
    QByteArray buf;
    buf.reserve(1 << 20);
    buf += kSpiralHead;
    char line[64];
    for (long i = kSpiralFirst; i < lines - 1; ++i) {
        buf.append(line, spiralLine(i, lines, line));
        if (buf.size() > (1 << 20) - 64) {
            if (f.write(buf) != buf.size())
                return false;
            buf.clear();
        }
    }
    buf += kSpiralTail;
    return f.write(buf) == buf.size();
}

} // namespace frezka::gui::test
