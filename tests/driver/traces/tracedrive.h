#pragma once
// The regression helper of serial traces (docs/serial-trace.md, "Traces as tests"): the
// operation a trace's header names, driven through the driver (MachineCore on SimRunner's
// virtual clock) against a far end, with what the driver showed (mode changes, errors, job
// ends) collected as event lines. recordTrace() drives it against the emulator and records;
// replayTrace() drives it against the replay of a trace and compares.
//
// Header keys the helper reads:
//   operation: connect | home | jog | job     (job: run `program`, see below)
//   variant: gve84 | gve64 | gve64-phantom | gve114
//   program: FILE.nc                          (job: beside the trace)
//   home: yes                                 (home before a jog or a job)
//   jog: AXIS MM MM_PER_MIN                   (jog: one step, e.g. "X 2 600")
//   pause-after-ms: MS, resume-after-ms: MS   (job: pause, then resume)
//   record-faults: RATE, record-seed: N       (recording only: the emulator's line faults)

#include "driver/emulator/serialtrace.h"

#include <string>

namespace frezka::driver::tracetest {

// Drives the header's operation against the emulator and returns the record (the header kept,
// entries and events new). `dir`: where the program file lies. False with `error`.
bool recordTrace(const emulator::SerialTrace &recipe, const std::string &dir,
                 emulator::SerialTrace &out, std::string &error);

// Drives the header's operation against the replay of `trace` and checks the driver sent every
// command of the trace in order, reached its end, and showed the same events. False with an
// English message naming the trace line.
bool replayTrace(const emulator::SerialTrace &trace, const std::string &dir, std::string &error);

} // namespace frezka::driver::tracetest
