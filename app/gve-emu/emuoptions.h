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
    bool help = false;
};

// Parses the arguments (without the program name). On error returns false and sets `error`.
bool parseEmuOptions(const QStringList &args, EmuOptions &options, QString &error);
QString emuHelpText();

} // namespace frezka::gveemu
