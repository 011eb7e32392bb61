#pragma once
// The RS274/NGC interpreter (LinuxCNC rs274ngc semantics) turning program text into a Toolpath.
//
// One pass over the text, line by line (no copy of the file, no per-line allocation): the
// Parser reads a line into a Block, the interpreter checks that every word is used by a code
// of the block (a leftover word is an error), then executes the block in LinuxCNC's order:
// parameter assignments, G93/G94, F, S, T, M6, M3/M4/M5, M7/M8/M9, G4, plane, units, G40,
// G43/G49, G54.., G61/G64, G90/G91, G90.1/G91.1, G98/G99, G10/G28/G30/G92, motion (with G53),
// M0/M1/M2/M30. O-word control flow jumps by byte offset inside the text, so loops and
// subroutines cost nothing when a program has none.
//
// Positions are kept in machine coordinates in mm (A in degrees); program coordinates are
// machine minus (work offset + G92 offset + tool length on Z). Every value read in G20 is
// converted to mm on entry.

#include "gcode/cuttercomp.h"
#include "gcode/error.h"
#include "gcode/linestate.h"
#include "gcode/parameters.h"
#include "gcode/parser.h"
#include "gcode/spline.h"
#include "gcode/toolpath.h"
#include "gcode/tooltable.h"

#include <array>
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace frezka::gcode {

inline constexpr char kAxisLetters[4] = {'x', 'y', 'z', 'a'}; // Block letters of the axes
inline constexpr std::uint32_t kAxisBits =
    (1u << ('x' - 'a')) | (1u << ('y' - 'a')) | (1u << ('z' - 'a')) | (1u << ('a' - 'a'));

// The outcome of a probe move (G38.x) the machine has run: where it stopped (machine mm, the
// trip point or the programmed end) and whether the probe input changed.
struct ProbeResult
{
    Point4 machineMm;
    bool tripped = true;
    friend bool operator==(const ProbeResult &, const ProbeResult &) = default;
};

struct Options
{
    bool collectAllErrors = false; // check mode: report every bad block and go on
    bool blockDelete = false;      // skip lines starting with '/' (LinuxCNC's default is off)
    // The end of the text without M2/M30/% ends the program (warning ImpliedProgramEnd and a
    // ProgramEnd event, as every grbl sender runs such files); false: FileEndedWithoutEnd /
    // FileEndedWithoutPercent errors, as LinuxCNC (the console's MDI lines, which never end).
    bool acceptMissingEnd = true;
    // Bounds on a program that never ends (an o-word loop or a recursion without an exit): the
    // lines executed and the toolpath's entries (moves, dwells, events; about 50 bytes each)
    // before the interpreter stops with TooManyBlocks / TooManyMoves, or LoopNeverEnds /
    // LoopMovesNeverEnd at the loop (or the recursive call) that was running. A 5 M-line
    // program stays well inside the defaults, and the default entries stay under 800 MB.
    std::uint64_t maxBlocks = 50'000'000;
    std::uint64_t maxMoves = 10'000'000;
    std::size_t maxErrors = 1000;  // check mode keeps this many (the rest are counted)
    std::size_t maxWarnings = 100; // warnings and notes kept (the rest are counted)
    // The tool table (LinuxCNC's rules: T, M61 Q, G43 H and G10 L1 P name tools in it, G43 takes
    // its offsets, G10 L1/L10/L11 change it). Without one every tool number is accepted and has
    // the length toolLengthMm gives it (0 when not listed) and no diameter.
    std::optional<ToolTable> toolTable;
    std::map<int, double> toolLengthMm;
    // Subroutine files, as LinuxCNC's `o<name> call` of a subroutine not defined yet: the file
    // name.ngc (o100 call: 100.ngc) in programDirectory (interpretFile sets it to the program's
    // folder when empty), then in each folder of subroutinePath in order (the machine profile's
    // program.subroutinePath, LinuxCNC's [RS274NGC]SUBROUTINE_PATH). The file's `o<name> sub`
    // .. `endsub` runs; errors there name the file (Error::file).
    std::string programDirectory;
    std::vector<std::string> subroutinePath;
    // #<_ini[section]name> values (LinuxCNC's INI_VARS), keyed "section]name" in lower case
    // (gcode/linuxcncini.h reads them from a LinuxCNC INI file); read-only to the program.
    std::map<std::string, double> iniValues;
    // Splines (G5, G5.1, G5.2/G5.3) are cut as chords no farther than this from the curve (the
    // machine profile's motion.chordToleranceMm, which arcs are chorded with too).
    double splineToleranceMm = 0.002;
    // State at the start of the program (added for the GUI: persisted work offsets and the
    // machine position the program starts from).
    std::array<std::array<double, 4>, 9> workOffsetsMm{}; // G54..G59.3, machine mm (#5221..)
    int coordinateSystem = 0;                             // active at the start: 0 = G54
    Point4 startMm;                                       // machine position (toolpath origin)
    // Run from a line: the state where this line (1-based) begins is recorded in Result::mark
    // (gcode/linestate.h); 0 = none. The program is interpreted whole all the same.
    std::uint32_t startLine = 0;
    // Programs that probe for themselves: the results of the probe moves already run, the first
    // probe executed first. Probe n (counted in execution order, loops and calls included) with
    // a result ends at its machineMm (the toolpath's probe entry ends there and the next move
    // starts there) and sets #5061..#5064 to it and #5070 to tripped; a probe without one keeps
    // its programmed end (both parameters as if it tripped there) and is provisional.
    std::vector<ProbeResult> probeResults;
    // Called now and then (every 65 536 lines) with the bytes read so far and the total.
    std::function<void(std::size_t done, std::size_t total)> progress;
    // Set from another thread to stop the interpretation soon (every 4 096 lines executed);
    // Result::cancelled then says so and the result is incomplete.
    const std::atomic_bool *cancel = nullptr;
};

struct Result
{
    Toolpath toolpath;
    // The first error, or in check mode every one in file order (an error repeated by a loop
    // or a call once), at most Options::maxErrors; errorsNotShown counts the others.
    std::vector<Error> errors;
    std::size_t errorsNotShown = 0;
    // Warnings (6xx) and notes (7xx) in file order: the program runs, but the user should know.
    // Each note is kept once and each warning code ten times; the others are counted.
    std::vector<Error> warnings;
    std::size_t warningsNotShown = 0;
    std::uint64_t linesRead = 0;
    bool ended = false;     // reached M2/M30 or the closing % (not an implied end)
    bool cancelled = false; // Options::cancel was set: the rest of the program was not read
    LineMark mark;          // Options::startLine's state, or why the program has none
    // The tool table after the program's G10 L1/L10/L11 (Options::toolTable otherwise); the
    // caller writes it back (writeToolTableFile) when the program has run.
    ToolTable toolTable;
    bool toolTableChanged = false;
    // G54..G59.3 as the program leaves them (G10 L2/L20; Options::workOffsetsMm otherwise),
    // machine mm; changed: they differ from Options::workOffsetsMm. The caller keeps them once
    // the program has run, as LinuxCNC keeps #5221.. in its parameter file.
    std::array<std::array<double, 4>, 9> workOffsetsMm{};
    bool workOffsetsChanged = false;
    // The first probe move without a result in Options::probeResults: its toolpath entry and
    // line; the path from there on depends on where that probe will stop (kNoEntry / 0: none).
    std::size_t provisionalEntry = kNoEntry;
    std::uint32_t provisionalLine = 0;
    std::size_t probes = 0; // probe moves executed
    static constexpr std::size_t kNoEntry = std::numeric_limits<std::size_t>::max();
    bool ok() const { return errors.empty(); }
};

class Interpreter final : private SystemParameters
{
public:
    explicit Interpreter(Options options = {});
    ~Interpreter() override;

    // Interprets a whole program. The text must outlive the call only. consumed, when set, is
    // called now and then with an offset below which the text has been read (loops may still
    // jump back there): a memory-mapped file can drop those pages from memory.
    Result run(std::string_view text, const std::function<void(std::size_t)> &consumed = {});

private:
    enum class FrameKind : std::uint8_t { Call, If, While, Do, Repeat };
    struct Frame
    {
        FrameKind kind;
        std::string label;
        std::size_t offset = 0;     // While: the while line; Do/Repeat: the body; Call: return
        std::uint32_t line = 0;     // line number at offset minus one
        std::int64_t remaining = 0; // Repeat
        std::uint32_t column = 1;   // of the O word on its opening line
        std::uint64_t turns = 0;    // While/Do/Repeat: jumps back to the body so far
        std::size_t source = 0;     // Call: the text to return to (SubDef::source)
    };
    struct SubDef
    {
        std::size_t offset = 0; // first body line
        std::uint32_t line = 0; // line number of the sub line
        std::size_t source = 0; // 0: the program; n: m_files[n - 1]
    };
    struct SubFile // a subroutine file read for o<name> call
    {
        std::string path;
        std::string text;
    };

    // Reading lines.
    bool nextLine(std::string_view *line);
    void jump(std::size_t offset, std::uint32_t lineBefore);
    void reset();

    // Blocks.
    bool processLine(std::string_view raw, Error *error);
    // Check mode, after an error in a block: the state the block would have set (its modes
    // without the unsupported codes, its end point), so that later blocks give no follow-on
    // errors (an arc checked from a point the program never meant). A motion that failed is
    // stood in for by a straight move to its end point (nothing runs when there are errors).
    void recoverBlock();
    void adoptTarget();
    bool executeBlock(Error *error);
    bool checkWords(int motion, Error *error);
    int motionToBe(Error *error);
    bool executeModes(Error *error);       // G93/G94 F S T M6 M3-M5 M7-M9 G4
    bool executeModalGroups(Error *error); // plane .. retract mode
    bool executeNonModal(Error *error);
    bool executeStops(Error *error);
    bool setOffsets(Error *error);
    // Tools (interp_tools.cpp).
    bool findTool(int tool, char word, ToolEntry *entry, Error *error) const;
    bool toolNumber(char word, int *tool, Error *error) const; // a whole, non-negative word
    bool selectTool(Error *error);                             // T, M6, M61
    bool toolLengthOffset(Error *error);                       // G43 G43.1 G43.2 G49
    bool setToolEntry(int l, Error *error);                    // G10 L1 L10 L11
    ToolEntry spindleTool() const; // the tool in the spindle's entry (zeros for T0)
    bool homeMove(bool g30, Error *error);

    // Run from a line (interp_mark.cpp).
    void markBefore(); // a line is about to run: is it the start line?
    // skipTo passed over the lines after `from` (an O line of this kind and label) to m_line.
    void noteSkipped(std::uint32_t from, OKind opening, const std::string &label);
    void finishMark(LineMark *mark) const;
    LineState lineState() const;

    // Motion (interp_motion.cpp).
    bool executeMotion(int motion, Error *error);
    struct Target
    {
        Point4 machine; // mm, every offset applied
        Point4 prog;    // program coordinates, mm
    };
    Target targetOf(bool machineCoords) const;
    void moveTo(const Target &target);
    void polarTarget(Target *target) const; // @ and ^ (LinuxCNC's polar coordinates)
    bool polarCheck(Error *error) const;
    bool cyclePolarStep(double *aa, double *bb, Error *error) const;
    bool straight(int motion, const Target &end, Error *error);
    bool arc(int motion, const Target &end, Error *error);
    bool arcCentreIjk(double su, double sv, double eu, double ev, std::uint32_t col, double *cu,
                      double *cv, Error *error) const;
    bool arcCentreR(int motion, double su, double sv, double eu, double ev, double *cu, double *cv,
                    Error *error) const;
    bool probe(int motion, const Target &end, Error *error);
    struct CycleWords
    {
        double r = 0, depth = 0, dwell = 0, peck = 0; // mm (depth: the normal axis word), s
        int repeats = 1;
    };
    bool cycleWords(int motion, CycleWords *words, Error *error) const;
    bool cycle(int motion, Error *error);
    void cycleTraverse(int plane, double aa, double bb, double cc);
    void cycleFeed(int plane, double aa, double bb, double cc);
    void cycleBody(int motion, double aa, double bb, double r, double clear, double cc,
                   double dwell, double peck);
    double feedFor(double lengthMm) const;
    // Splines (interp_spline.cpp).
    bool spline(int motion, const Target &end, Error *error); // G5, G5.1
    bool nurbsPoint(const Target &end, Error *error);         // G5.2 and its control points
    bool nurbsEnd(Error *error);                              // G5.3
    bool nurbsEndAlone(Error *error) const; // G5.3's block: no other motion, no axis words
    bool splineAllowed(int motion, Error *error) const;
    // A motion or M2/M30 before G5.3: an error, and the curve is dropped (reported once).
    bool nurbsPending(int motion, Error *error);
    // The curve as feed moves in machine coordinates, the last one ending at endMachine.
    void appendSpline(const std::vector<SplinePoint> &points, unsigned order,
                      const Point4 &endMachine);
    void event(EventKind kind, double value = 0, double p = 0, double q = 0);

    // Cutter radius compensation (interp_comp.cpp).
    bool compOn(Error *error);                        // G41 G42 G41.1 G42.1
    bool compOff(Error *error);                       // G40 (also M2/M30)
    bool compAllows(Error *error) const;              // the block's codes while it is on
    bool compFlush(double u, double v, Error *error); // the queued moves end at (u, v)
    bool compFlushHere(Error *error);                 // ... where the tool is (M0, G40)
    bool compStraight(int motion, const Target &target, Error *error);
    void compCorner(int motion, double ou, double ov, double mu, double mv, const Point4 &end,
                    double feed);
    bool compArcNext(int motion, const Target &target, int turns, Error *error);
    bool compInsideCorner(double beta, double theta, double gamma, double pu, double pv, double ou,
                          double ov, Error *error);
    bool compArc(int motion, const Target &target, int turns, Error *error);
    bool compArcFirst(int motion, const Target &target, int turns, Error *error);
    bool compArcCorner(double beta, double theta, double cu, double cv, double arcRadius, int turn,
                       Error *error);
    void compEnqueue(MotionKind kind, const Point4 &end, double feed, double du, double dv,
                     const ArcInfo *arc, double originalTurns);
    // The plane's (u, v) in program coordinates, w and a in machine coordinates: the machine point.
    Point4 compPoint(double u, double v, double w, double a) const;

    // O-words (interp_oword.cpp).
    bool executeOword(Error *error);
    bool skipTo(const std::string &label, std::initializer_list<OKind> kinds, OKind *found,
                Error *error);
    bool owordCondition(double *value, Error *error);
    bool owordIf(const std::string &label, Error *error);
    bool owordWhile(const std::string &label, Error *error);
    bool callSub(Error *error);
    // Subroutine files (interp_subfile.cpp).
    bool subFileFor(const std::string &label, std::string *path) const; // on the search path
    // Reads `path` and finds its `o<label> sub` line: m_subs[label] names it; the reading
    // position stays where it was.
    bool loadSubFile(const std::string &label, const std::string &path, std::uint32_t column,
                     Error *error);
    void enterSource(std::size_t source); // reading goes on in that text (jump sets where)
    // The program's line a toolpath entry is attributed to: inside a subroutine file, the line
    // of the program's call that led there.
    std::uint32_t pathLine() const { return m_source == 0 ? m_line : m_fileCallLine; }
    const std::string &sourcePath() const; // empty for the program
    bool checkNestedSub(const std::string &label, Error *error) const;
    bool returnFromSub(Error *error);
    bool loopJump(bool isBreak, Error *error);
    std::uint32_t oColumn() const { return m_parser.columnAt(m_block.oColumn); }
    // A bound of Options was passed: the error at the loop that has turned most (or the first
    // recursive call), naming the line reached; at that line when no loop or call runs.
    Error boundError(ErrorCode plain, ErrorCode inLoop, std::uint64_t bound) const;

    // Modal state save and restore, M70-M73 (interp_state.cpp).
    struct ModalContext
    {
        bool valid = false, restoreOnReturn = false;
        bool metric = true;
        // 10 x the G code: plane, compensation, distance, feed mode, coordinate system, tool
        // length, retract mode, arc distance, G92 applied (G92.3) or not (G92.2).
        std::array<int, 9> codes{};
        int pathMode = 2;
        double pathP = 0, pathQ = 0, feed = 0, speed = 0; // in the saved units
        int spindle = 0;
        bool mist = false, flood = false;
    };
    ModalContext modalNow() const;
    std::size_t callDepth() const;
    ModalContext &contextHere();
    bool modalState(Error *error); // a line with M70-M73
    bool restoreModal(const ModalContext &saved, Error *error);
    bool runStateLine(const std::string &text, Error *error);
    bool leaveCallContext(Error *error); // after return/endsub: M73's restore

    // Coordinates.
    double offset(int axis) const // every block's target: inline
    {
        return m_origin[m_coord][axis] + m_g92[axis] + m_toolOffset[axis];
    }
    Point4 programPosition() const { return m_prog; }
    std::array<double, 4> offsets() const;
    // After an offset changed: the program position moves by the change (rs274ngc's
    // current = current + old offset - new offset), the machine position stays.
    void shiftProgram(const std::array<double, 4> &oldOffsets);
    // Coordinate-system rotation (interp_rotation.cpp).
    double rotation() const { return m_rotationDeg[m_coord]; } // degrees, counter-clockwise
    Point4 toMachine(const Point4 &prog) const;                // every offset and the rotation
    Point4 toProgram(const Point4 &machine) const;
    Point4 turnedCentre(double cu, double cv) const; // a G17 arc's centre (program) in machine
    // After the active system or an offset changed: as shiftProgram, or with a rotation before or
    // after the change the current point found anew in the system (rs274ngc's
    // find_current_in_system).
    void shiftProgram(const std::array<double, 4> &oldOffsets, double oldRotationDeg);
    void setSystemXY(int system, bool l20, double rotationDeg); // G10 L2/L20 X Y R
    void carryActiveSystem(const std::array<double, 4> &oldOrigin, double oldRotationDeg);
    bool rotationAllows(int motion, Error *error) const; // arcs in G17 only under a rotation
    double unit() const { return m_metric ? 1.0 : 25.4; }
    double lengthWord(char c) const { return m_block.get(c) * unit(); }
    bool fail(ErrorCode code, char word, std::string detail, Error *error) const;
    // Records a warning or note at pos of the current line (0: the block start).
    void warnAt(ErrorCode code, std::uint32_t pos, std::string detail);
    void warn(ErrorCode code, std::uint32_t line, std::uint32_t column, std::string detail);
    // A feed move runs at a feed set before a change of units (FeedUnitsChanged, once per F).
    void checkFeedUnits();
    double feedMm() const { return m_inverseTime ? 0.0 : m_feedMm; } // modal feed, mm/min
    // pos: offset into the normalized line (Block's word positions), 0 for the block start.
    bool failAt(ErrorCode code, std::uint32_t pos, std::string detail, Error *error) const;

    // SystemParameters
    bool systemNumbered(int index, double *value) const override;
    bool systemNamed(std::string_view name, double *value) const override;

    Options m_options;
    Parameters m_params;
    Parser m_parser;
    Block m_block;
    std::vector<Assignment> m_assignments;
    std::vector<double> m_args;
    Toolpath m_toolpath;

    // Source reading.
    std::string_view m_text;
    std::size_t m_next = 0;      // offset of the next line
    std::size_t m_lineStart = 0; // offset of the current line
    std::uint32_t m_line = 0;    // current line number (1-based)
    std::uint64_t m_executed = 0;
    bool m_percentStarted = false;
    bool m_sawContent = false;
    bool m_ended = false;
    bool m_parsed = false; // the current line was parsed (an error came from executing it)

    std::vector<Error> m_warnings;
    std::size_t m_warningsNotShown = 0;
    std::unordered_map<int, int> m_warningCount; // per code

    // Subroutine files read so far and the text being read (0: the program, m_program).
    std::vector<std::unique_ptr<SubFile>> m_files;
    std::size_t m_source = 0;
    std::string_view m_program;
    std::uint32_t m_fileCallLine = 0; // the program's line whose call entered a file

    // Control flow.
    std::vector<Frame> m_frames;
    std::unordered_map<std::string, SubDef> m_subs;
    double m_value = 0;
    bool m_valueReturned = false;

    // Modal state (LinuxCNC defaults: G17 G21 G40 G49 G54 G64 G80 G90 G94 G99 G91.1).
    Point4 m_pos; // machine position, mm
    // Program position, kept like rs274ngc's current_x.. (not recomputed from m_pos, so values
    // the program compares, e.g. a cycle's clearance height, stay exactly as programmed).
    Point4 m_prog;
    std::array<std::array<double, 4>, 9> m_origin{}; // G54..G59.3 offsets, mm
    std::array<double, 9> m_rotationDeg{};           // G10 L2 R of G54..G59.3, degrees
    std::array<double, 4> m_g92{};                   // active G92 offset, mm
    std::array<double, 4> m_g92Saved{};              // #5211.. (kept by G92.2, restored by G92.3)
    bool m_g92Enabled = false;
    std::array<double, 4> m_g28{}, m_g30{}; // stored positions, machine mm
    std::array<double, 4> m_toolOffset{};   // G43's offsets in force, mm (A degrees)
    int m_toolLengthG = 490;                // the last G43/G43.1/G43.2/G49, 10 x the code
    std::vector<ModalContext> m_contexts;   // M70/M73 state per call level (0: top)
    ToolTable m_tools;                      // Options::toolTable as the program changes it
    bool m_toolsStrict = false;             // a table was given: tools must be in it
    bool m_toolsChanged = false;
    int m_coord = 0;        // 0 = G54 .. 8 = G59.3
    int m_motion = 800;     // 10 x G code of the motion mode
    int m_motionNext = 800; // the motion the block is about to execute (polarCheck)
    int m_plane = 170;
    bool m_absolute = true;
    bool m_arcAbsolute = false;
    bool m_inverseTime = false;
    bool m_metric = true;
    bool m_retractToR = true; // G99 (rs274ngc starts in G99)
    double m_feed = 0;        // F as programmed (units/min or 1/min in G93)
    // The physical feed: F in the units in force when F was executed (LinuxCNC's canon keeps
    // it across a later G20/G21). Where F and the units change were, for FeedUnitsChanged.
    double m_feedMm = 0;
    bool m_feedMetric = true;
    bool m_feedUnitsWarned = false;
    std::uint32_t m_feedLine = 0;
    std::uint32_t m_unitsLine = 0, m_unitsColumn = 0;
    double m_speed = 0; // S, rpm
    int m_spindle = 0;  // 0 off, 1 cw, -1 ccw
    int m_tool = 0, m_selectedTool = 0;
    bool m_mist = false, m_flood = false;
    int m_pathMode = 2;                                             // 0 G61, 1 G61.1, 2 G64
    double m_pathP = 0, m_pathQ = 0;                                // mm
    double m_cycleR = 0, m_cycleCC = 0, m_cycleP = 0, m_cycleQ = 0; // mm / s as programmed
    double m_cycleIl = 0; // initial level of consecutive cycles
    bool m_cycleIlValid = false;
    // Run from a line: the mark, a skip over the start line, a call that ran it.
    LineMark m_mark;
    bool m_marked = false;
    bool m_lookingAhead = false; // callSub searching a subroutine's definition further down
    LineMarkRefusal m_skipRefusal = LineMarkRefusal::None;
    std::uint32_t m_skipLine = 0, m_callLine = 0;
    std::string m_skipLabel, m_callLabel;
    // Cutter radius compensation; while it moves the path, m_pos is the tool's (compensated)
    // position and m_prog the programmed point (rs274ngc's current_x and program_x).
    CutterComp m_comp;
    // Splines: the NURBS control points since G5.2 (program mm; the first is where it starts),
    // its order and line; G5's first control point when I and J are left out (-P, -Q of the
    // previous G5 as written, in the units in force when used: rs274ngc's cycle_i, cycle_j).
    std::vector<SplinePoint> m_nurbs;
    unsigned m_nurbsOrder = 3;
    std::uint32_t m_nurbsLine = 0;
    double m_splineI = 0, m_splineJ = 0;
    Point4 m_probe; // #5061.. (program coordinates, mm)
    bool m_probed = false;
    std::size_t m_probes = 0;                          // probe moves executed so far
    std::size_t m_provisionalEntry = Result::kNoEntry; // Result::provisionalEntry
    std::uint32_t m_provisionalLine = 0;
};

// Interprets a file (memory-mapped). A file that cannot be read gives FileOpenFailed.
Result interpretFile(const std::string &path, const Options &options = {});
Result interpretText(std::string_view text, const Options &options = {});

} // namespace frezka::gcode
