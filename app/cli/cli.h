#pragma once
// frezka-cli subcommand registry. Each subcommand lives in its own cmd_<name>.cpp and registers
// itself at static-initialisation time:
//
//   static int runCheck(const QStringList &args);   // args exclude "frezka-cli" and "check"
//   FREZKA_CLI_COMMAND(check, "check FILE", "Check a G-code program and print a summary", runCheck)
//
// A command returns the process exit code (0 ok, 1 error in the input, 2 usage error) and
// prints errors to stderr.

#include <QStringList>

#include "gcode/interpreter.h"
#include "machine/machineconfig.h"
#include "machine/planner.h"

#include <functional>
#include <map>
#include <string>

namespace frezka::cli {

struct Command
{
    std::string usage;   // "check FILE"
    std::string summary; // one line for the overview
    std::function<int(const QStringList &)> run;
};

// Name -> command, sorted by name.
std::map<std::string, Command> &commands();
bool registerCommand(const std::string &name, Command command);

// Writes to stdout / stderr (UTF-8) without Qt's logging decorations.
void out(const QString &text);
void err(const QString &text);
// "FILE:LINE: KIND<message>\n" for a plan error or warning (its own "line N: " prefix dropped).
QString planMessage(const QString &file, const machine::PlanError &error, const QString &kind);
// Prints the interpreter's warnings and notes ("FILE:LINE:COL: warning: ...") and how many were
// not shown, to stderr.
void printGcodeWarnings(const QString &file, const gcode::Result &result);
// Prints what became of a profile's retired keys ("note: ..."), one line each, to stderr.
void printConfigNotes(const machine::ConfigResult &result);

} // namespace frezka::cli

#define FREZKA_CLI_COMMAND(name, usage, summary, fn)                                               \
    static const bool frezkaCliRegistered_##name =                                                 \
        ::frezka::cli::registerCommand(#name, {usage, summary, fn})
