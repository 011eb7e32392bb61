#pragma once
// MdiSession: the console's G-code (MDI), one line at a time, with a modal state that lasts
// from line to line as in LinuxCNC's MDI: G90/G91, G20/G21, F, S, the plane, the motion mode,
// G93/G94, the active coordinate system and G92 all carry over, and so do the interpreter's
// parameters. One gcode::Interpreter stays alive for the session (its run() keeps every modal
// field; each line ends without M2, so the "file ended without M2" report is not an error
// here). Before a line, when the machine is no longer where the last line left it (a jog, a
// program, homing) or the work offsets were changed elsewhere, a short internal script brings
// the interpreter to the machine's position and the offsets while keeping its modes. After a
// line, the modal state and the offsets are read back from the interpreter's parameters (as
// G4 dwells in a discarded toolpath), so that a G10 / G92 / G55 typed in the console reaches
// the session's work offsets. M2 / M30 end the session's modes: the next line starts afresh.

#include "session/workoffsets.h"

#include "gcode/error.h"
#include "gcode/toolpath.h"

#include <QString>

#include <memory>
#include <string_view>
#include <vector>

namespace frezka::gcode {
class Interpreter;
}

namespace frezka::session {

// The console's modes after its last line (program units as programmed).
struct ModalState
{
    bool metric = true;
    bool absolute = true;
    bool inverseTime = false;
    int plane = 17;      // 17, 18, 19
    double motion = 0;   // G code of the motion mode (0, 1, 2, 3, 38.2, 80, 81 ...)
    double feed = 0;     // F, units per minute (G94) or 1/min (G93)
    double rpm = 0;      // S
    int coordSystem = 0; // 0 = G54 .. 8 = G59.3
    // "G1 G17 G21 G90 G94 G54 F100 S0", for the console.
    QString text() const;
    friend bool operator==(const ModalState &, const ModalState &) = default;
};

class MdiSession
{
public:
    MdiSession();
    ~MdiSession();

    struct Outcome
    {
        gcode::Toolpath toolpath;         // the line's moves from the machine position
        std::vector<gcode::Error> errors; // non-empty: nothing should move
        bool offsetsChanged = false;      // the line set G10 / G92 / G5x: see offsets
        OffsetState offsets;              // the offsets after the line
        bool ok() const { return errors.empty(); }
    };

    // Interprets one line from the machine position (mm) with the given work offsets.
    Outcome interpret(std::string_view line, const Axes4 &machineMm, const OffsetState &offsets);
    const ModalState &modal() const { return m_modal; }
    // Forgets the modal state (a fresh interpreter with LinuxCNC's defaults for the next line).
    void reset();

private:
    bool start(const Axes4 &machineMm, const OffsetState &offsets);
    bool sync(const Axes4 &machineMm, const OffsetState &offsets);
    bool readBack(OffsetState *offsets);

    std::unique_ptr<gcode::Interpreter> m_interp;
    Axes4 m_at{};          // where the interpreter's last line ended (machine mm)
    OffsetState m_offsets; // the offsets the interpreter holds
    ModalState m_modal;
    bool m_inSync = false; // m_at and m_offsets are exactly the interpreter's
};

} // namespace frezka::session
