// Subroutine files, as LinuxCNC's rs274ngc (interp_o_word.cc control_back_to, find_ngc_file):
// `o<name> call` of a subroutine not defined yet reads name.ngc from the program's folder or a
// folder of the subroutine path, skips to its `o<name> sub` line and runs the body there; return
// and endsub come back to the calling text. Only that subroutine runs from the file: another
// `sub` line reached inside a called subroutine, or a call from a file of a subroutine that is
// neither defined yet nor in a file of its own, is an error (LinuxCNC since 2.10, #3880).
#include "interpreter.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace frezka::gcode {

namespace {

std::string labelText(const std::string &label)
{
    return "o" +
           (label.empty() || (label[0] >= '0' && label[0] <= '9') ? label : "<" + label + ">");
}

} // namespace

const std::string &Interpreter::sourcePath() const
{
    static const std::string kProgram;
    return m_source == 0 ? kProgram : m_files[m_source - 1]->path;
}

void Interpreter::enterSource(std::size_t source)
{
    m_source = source;
    m_text = source == 0 ? m_program : std::string_view(m_files[source - 1]->text);
}

bool Interpreter::subFileFor(const std::string &label, std::string *path) const
{
    namespace fs = std::filesystem;
    const std::string name = label + ".ngc";
    auto tryIn = [&](const std::string &dir) {
        if (dir.empty())
            return false;
        std::error_code ec;
        const fs::path p = fs::path(dir) / name;
        if (!fs::is_regular_file(p, ec))
            return false;
        *path = p.lexically_normal().string();
        return true;
    };
    if (tryIn(m_options.programDirectory))
        return true;
    for (const std::string &dir : m_options.subroutinePath) {
        if (tryIn(dir))
            return true;
    }
    return false;
}

bool Interpreter::loadSubFile(const std::string &label, const std::string &path,
                              std::uint32_t column, Error *error)
{
    std::size_t source = 0;
    for (std::size_t i = 0; i < m_files.size() && source == 0; ++i)
        source = m_files[i]->path == path ? i + 1 : 0;
    if (source == 0) {
        std::ifstream in(path, std::ios::binary);
        std::stringstream text;
        if (!in || !(text << in.rdbuf())) {
            *error = {ErrorCode::FileOpenFailed, m_line, column, path, sourcePath()};
            return false;
        }
        m_files.push_back(std::make_unique<SubFile>(SubFile{path, text.str()}));
        source = m_files.size();
    }
    const std::size_t from = m_source, next = m_next, start = m_lineStart;
    const std::uint32_t line = m_line;
    enterSource(source);
    jump(0, 0);
    OKind found = OKind::None;
    m_lookingAhead = true; // not the program's lines: nothing for run-from-line to note
    const bool defined = skipTo(label, {OKind::Sub}, &found, error);
    m_lookingAhead = false;
    if (defined)
        m_subs[label] = {m_next, m_line, source};
    else if (error->code == ErrorCode::OwordNotClosed)
        *error = {ErrorCode::SubroutineFileWithoutSub,
                  0,
                  0,
                  labelText(label) + kDetailSeparator + path,
                  {}};
    else
        error->file = path; // an error in the file names it
    enterSource(from);
    m_next = next;
    m_lineStart = start;
    m_line = line;
    Error ignored;
    m_parser.normalize(m_text.substr(start, next - start), line, &ignored); // the call again
    if (!defined && error->line == 0) { // the call's error, at the call
        error->line = line;
        error->column = column;
        error->file = sourcePath();
    }
    return defined;
}

bool Interpreter::checkNestedSub(const std::string &label, Error *error) const
{
    for (auto f = m_frames.rbegin(); f != m_frames.rend(); ++f) {
        if (f->kind != FrameKind::Call)
            continue;
        if (f->label == label)
            return true;
        return failAt(ErrorCode::NestedSubDefinition, m_block.oColumn,
                      labelText(label) + kDetailSeparator + labelText(f->label), error);
    }
    return true;
}

} // namespace frezka::gcode
