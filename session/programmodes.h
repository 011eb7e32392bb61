#pragma once
// The program's modal state at a line, for the status panel: LinuxCNC's active G codes (motion,
// plane, cutter compensation, units, distance mode, feed mode, coordinate system, tool length,
// retract mode, path control, arc distance), the tool in the spindle (T then M6), the spindle
// and the coolant as programmed. Read from the text with the interpreter's own parser, so that
// comments, line numbers and words are taken exactly as the interpreter takes them.
//
// ModalScanner reads forward: at(line) goes on from the last line asked (a running job's line
// only grows, so a whole job costs one pass); a line before it starts again from the top. Lines
// are read in file order: O-word flow (loops, subroutines) is not followed, and a word whose
// value needs the interpreter's parameters reads as 0.

#include "session/programtext.h"

#include "gcode/parser.h"

#include <QString>

#include <array>
#include <cstdint>
#include <memory>

namespace frezka::session {

struct ProgramModes
{
    std::array<std::int16_t, gcode::kGGroupCount> g{}; // 10 x code per group, -1 = none
    int tool = 0;                                      // in the spindle (M6 loaded it), 0 = none
    int spindle = 0;                                   // 1 M3, -1 M4, 0 M5
    bool mist = false;                                 // M7
    bool flood = false;                                // M8
    // "G1 G17 G40 G21 G90 G94 G54 G49 G99 G64 G91.1", LinuxCNC's order.
    QString gText() const;
    // "M3 M8" (M5 M9 when both are off).
    QString mText() const;
    friend bool operator==(const ProgramModes &, const ProgramModes &) = default;
};

// The state at the start of a program (LinuxCNC's defaults; coordinateSystem 0 = G54).
ProgramModes startModes(int coordinateSystem);

class ModalScanner
{
public:
    ModalScanner(std::shared_ptr<const ProgramText> text, int coordinateSystem);
    ~ModalScanner();
    // The state once `line` (1-based; 0 = before the first) has run.
    const ProgramModes &at(std::uint32_t line);

private:
    void restart();
    void apply(const gcode::Block &block);

    struct Reader;
    std::shared_ptr<const ProgramText> m_text;
    int m_coordinateSystem = 0;
    std::unique_ptr<Reader> m_reader;
    ProgramModes m_modes;
    int m_selected = 0;       // T
    std::uint32_t m_line = 0; // lines read
};

} // namespace frezka::session
