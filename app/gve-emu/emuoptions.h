#pragma once
// Command line of gve-emu: parsed into plain values, every error named.

#include "driver/emulator/simulation.h"

#include <QString>
#include <QStringList>

namespace frezka::gveemu {

struct EmuOptions
{
    emulator::SimulationOptions simulation;
    QString linkPath;     // --link: symlink to the slave pty
    QString replayFile;   // --replay: play this serial trace instead of emulating
    bool verbose = false; // --verbose: log traffic to stderr
    bool wheel = false;   // --wheel: turn the MPG wheel by lines on stdin (parseWheelLine)
    bool help = false;
};

// One turn of the simulated MPG wheel: "AXIS STEP DETENTS", e.g. "X 10 -5" (axis switch X, Y,
// Z, A or 4 = the 4th position; step switch 1, 10 or 100; signed detents).
struct WheelTurn
{
    int axisPosition = 0;
    int multiplier = 1;
    int detents = 0;
};
// Parses one stdin line of --wheel. On error returns false and sets `error`.
bool parseWheelLine(const QString &line, WheelTurn &turn, QString &error);

// Parses the arguments (without the program name). On error returns false and sets `error`.
bool parseEmuOptions(const QStringList &args, EmuOptions &options, QString &error);
QString emuHelpText();

} // namespace frezka::gveemu
