#pragma once
// Lexer and parser for one RS274/NGC line (LinuxCNC dialect).
//
// normalize() strips comments, spaces and tabs and lower-cases the line into a reused buffer,
// remembering each kept character's source column. parse() then reads the words into a Block:
// every value (numbers, #parameters, [expressions], unary functions) is evaluated as it is read,
// with the parameter values from before the line; parameter assignments are collected and only
// applied by the interpreter after the whole line was read (LinuxCNC semantics). G and M codes
// are sorted into their modal groups here, so a second code of the same group is an error at its
// column. No heap allocation per line once the buffers have grown to the longest line.

#include "gcode/error.h"
#include "gcode/parameters.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace frezka::gcode {

// G modal groups (LinuxCNC numbering).
enum GGroup : int {
    kGNonModal = 0,
    kGMotion = 1,
    kGPlane = 2,
    kGDistance = 3,
    kGArcDistance = 4,
    kGFeedMode = 5,
    kGUnits = 6,
    kGCutterComp = 7,
    kGToolLength = 8,
    kGRetract = 10,
    kGCoordSystem = 12,
    kGPathControl = 13,
    kGSpindleMode = 14,
    kGGroupCount = 16,
};

// M modal groups (LinuxCNC numbering).
enum MGroup : int {
    kMStop = 4,
    kMToolChange = 6,
    kMSpindle = 7,
    kMCoolant = 8,
    kMState = 10, // M70-M73 (Frezka's own group; M100-M199 are refused in it)
    kMGroupCount = 11,
};

enum class OKind : std::uint8_t {
    None,
    Sub,
    EndSub,
    Call,
    Return,
    If,
    ElseIf,
    Else,
    EndIf,
    While,
    EndWhile,
    Do,
    Repeat,
    EndRepeat,
    Break,
    Continue,
};
const char *okindName(OKind kind);

struct Assignment
{
    int index = 0;         // numbered parameter, 0 when named
    std::string_view name; // named parameter (into the parser's line buffer)
    double value = 0;
    std::uint32_t column = 0;
};

struct Block
{
    // Letter words other than G, M, N, O: bit (c - 'a') set when present. Word positions
    // (column[], gColumn[], mColumn[], oColumn) are offsets into the normalized line;
    // Parser::columnAt() turns them into source columns when an error is reported.
    // LinuxCNC's polar coordinates take the two bits after the letters: @ radius, ^ angle.
    static constexpr int kRadius = 26, kAngle = 27;
    std::uint32_t letters = 0;
    double value[28];
    std::uint32_t column[28];
    // G codes as 10 x the number (G38.2 -> 382), one per modal group; -1 when absent.
    std::int16_t g[kGGroupCount];
    std::uint32_t gColumn[kGGroupCount];
    std::uint32_t gMask = 0;
    // M codes, one per modal group.
    std::int16_t m[kMGroupCount];
    std::uint32_t mColumn[kMGroupCount];
    std::uint32_t mMask = 0;
    // O word (only on its own line): the keyword, its label ("100" or "name") and where the
    // arguments start in the parser's buffer (evaluated only when the line is executed).
    OKind oKind = OKind::None;
    std::string oLabel;
    std::uint32_t oColumn = 0;
    std::size_t oArgsPos = 0;

    bool has(char c) const { return letters & (1u << (c - 'a')); }
    double get(char c) const { return value[c - 'a']; }
    std::uint32_t col(char c) const { return column[c - 'a']; }
    bool hasPolar() const { return letters & (3u << kRadius); }
    bool hasWord(int index) const { return letters & (1u << index); }
    bool hasG(int group) const { return gMask & (1u << group); }
    bool hasM(int group) const { return mMask & (1u << group); }
};

class Parser
{
public:
    explicit Parser(Parameters &params);

    // Copies the line without comments and blanks, lower case. False + error on a bad comment.
    // Sets isEmpty()/isPercent()/hasBlockDelete(). readableAfter: bytes after raw's end that may
    // be read (never used): the rest of the program text, for reading 16 bytes at a time.
    // (normalize.cpp)
    bool normalize(std::string_view raw, std::uint32_t line, Error *error,
                   std::size_t readableAfter = 0);
    bool isEmpty() const { return m_text.empty(); }
    bool isPercent() const { return m_text.size() == 1 && m_text[0] == '%'; }
    bool hasBlockDelete() const { return m_blockDelete; }
    // The text of an (abort, text) comment on the line (LinuxCNC ends the program there), and
    // its column (1-based); 0 when the line has none.
    std::uint32_t abortColumn() const { return m_abortColumn; }
    const std::string &abortText() const { return m_abortText; }

    // Reads the normalized line into block and assignments (cleared first).
    bool parse(Block &block, std::vector<Assignment> &assignments, Error *error);
    // After an error in check mode: the line again, its unsupported codes and words skipped, so
    // that the interpreter can take the state the block would have set (no follow-on errors).
    bool parseSkippingUnsupported(Block &block, std::vector<Assignment> &assignments, Error *error);

    // Only the O word of the normalized line (no expression evaluated): for skipping.
    // False when the line has no O word; error only for a malformed O word.
    bool peekOword(OKind *kind, std::string *label, Error *error);

    // Evaluates the bracketed O-word arguments of the last parsed line, up to the line's end.
    bool owordArgs(const Block &block, std::vector<double> *args, Error *error);

    std::string_view text() const { return m_text; }
    // 1-based source column of an offset into the normalized line (computed only for errors).
    std::uint32_t columnAt(std::size_t pos) const;

private:
    void noteAbortComment(std::string_view comment, std::size_t open);
    bool fail(ErrorCode code, std::size_t pos, std::string detail, Error *error) const;

    bool readOword(Block &block, Error *error);
    // evaluate: compute a label given as a value (o#<sub>, o[...]); false (skipping): step over
    // it, the label left empty so that it closes no block.
    bool readOwordHead(std::size_t *pos, OKind *kind, std::string *label, std::uint32_t *col,
                       bool evaluate, Error *error);
    std::size_t skipComputedLabel(std::size_t p) const; // at '#' or '[': the offset after it
    bool readGCode(Block &block, Error *error);
    bool readMCode(Block &block, Error *error);
    bool readAssignment(std::vector<Assignment> &assignments, Error *error);
    bool readLineNumber(Error *error);

    // Values (expression.cpp).
    bool readRealValue(double *value, Error *error);
    bool readNumber(double *value, Error *error);
    bool readInteger(double *value, std::size_t startPos, Error *error);
    bool readExists(std::size_t start, double *value, Error *error); // after "exists", at '['
    bool readExpression(double *value, Error *error);
    bool readBinary(int minPrecedence, double *value, Error *error);
    bool readOperator(int *op, std::size_t *length) const;
    bool readUnary(double *value, Error *error);
    bool readParameter(double *value, Error *error);
    bool readParameterRef(int *index, std::string_view *name, Error *error);
    bool readName(std::string_view *name, Error *error);
    bool applyOperator(int op, double left, double right, double *out, std::size_t pos,
                       Error *error) const;

    Parameters &m_params;
    // normalize() writes each line into m_buffer, which only grows (no resize per line), and
    // m_text is the line there; a NUL follows it.
    std::string m_buffer;
    std::string_view m_text;
    std::string_view m_raw; // the source line of m_text
    std::uint32_t m_line = 0;
    std::size_t m_pos = 0;
    bool m_blockDelete = false;
    std::uint32_t m_abortColumn = 0;
    std::string m_abortText;
    bool m_skipUnsupported = false;
};

// Modal group of G code (10 x number), -1 if unknown; *supported false for known codes that
// Frezka refuses (with a reason for the message).
int gGroup(int code10, bool *supported, const char **reason);
int mGroup(int code, bool *supported, const char **reason);
// "G38.2" / "M30" for messages.
std::string gName(int code10);

// The '\n' characters in text, 16 bytes at a time (normalize.cpp): a program's line count.
std::size_t countNewlines(std::string_view text);

} // namespace frezka::gcode
