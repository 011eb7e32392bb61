#pragma once
// The options every frezka-cli command on a program takes (check, plan, run): the machine
// profile and where the program's zero is on the machine, read into the session layer's
// OffsetState, and the program checked with them as the GUI checks it (session::
// interpretProgram). --offset G54:X,Y,Z[,A] (any of G54 .. G59.3, repeatable) sets a system's
// offset (machine mm of its zero, as G10 L2 does); --work-zero X,Y,Z[,A] is --offset G54:... .
// A program starts in G54, as after LinuxCNC's reset, and selects others itself.
// --height-map FILE bends the checked program to a probed surface (gcode/heightmap.h,
// docs/height-map.md) before it is planned; the output says so, with the map's range.

#include "session/programplanner.h"
#include "session/workoffsets.h"

#include "machine/machineconfig.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <optional>

namespace frezka::cli {

struct ProgramCli
{
    Q_DECLARE_TR_FUNCTIONS(ProgramCli)
};

struct ProgramOptions
{
    QString machine; // the profile: a path or a shipped name (gve84); empty: the GVE64 defaults
    session::OffsetState offsets;
    bool offsetsGiven = false;
    QString heightMap; // a height-map file (docs/height-map.md); empty: none
};

// "[--machine PROFILE] [--offset G54:X,Y,Z[,A]]... [--work-zero X,Y,Z[,A]] [--height-map FILE]"
QString programOptionsUsage();
// When args[i] is --machine, --offset or --work-zero: takes it and its value (i moves on) and
// returns true; *ok is false when the value is malformed (the reason on stderr).
bool takeProgramOption(const QStringList &args, int &i, ProgramOptions *options, bool *ok);
// The profile of --machine (its notes and errors on stderr), or the shipped GVE64 one.
std::optional<machine::MachineConfig> loadProfile(const QString &path);
// The file read and interpreted from the offsets at the machine's zero; every error on stderr
// as FILE:LINE:COL: message; nullopt on any (*errorCount: how many). With --height-map the
// toolpath is bent to the map (a cut outside it is an error naming its line). startLine: the state
// where that line begins is in the outcome's mark (run from a line), 0 = none. requestOut: the
// request it was interpreted with (to interpret it again, session/probefollow.h).
std::optional<session::InterpretOutcome>
interpretFile(const QString &file, const ProgramOptions &options, int *errorCount = nullptr,
              std::uint32_t startLine = 0, session::InterpretRequest *requestOut = nullptr);

} // namespace frezka::cli
