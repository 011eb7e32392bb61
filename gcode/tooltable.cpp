#include "tooltable.h"

#include <QFile>
#include <QSaveFile>
#include <QString>

#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

namespace frezka::gcode {

namespace {

constexpr const char kOffsetLetters[] = "xyzabcuvw";

bool readNumber(std::string_view word, double *value)
{
    std::string_view s = word.substr(1);
    if (!s.empty() && s.front() == '+')
        s.remove_prefix(1);
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), *value);
    return ec == std::errc() && end == s.data() + s.size() && std::isfinite(*value) && !s.empty();
}

bool readInt(std::string_view word, int *value)
{
    double v = 0;
    if (!readNumber(word, &v) || v != std::floor(v) || std::fabs(v) > 1e9)
        return false;
    *value = static_cast<int>(v);
    return true;
}

// One word of an entry; false when the letter is unknown or its value bad.
bool readWord(std::string_view word, ToolEntry *e, bool *sawT)
{
    const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(word.front())));
    double v = 0;
    if (c == 't') {
        *sawT = true;
        return readInt(word, &e->tool) && e->tool > 0;
    }
    if (c == 'p')
        return readInt(word, &e->pocket) && e->pocket >= 0;
    if (c == 'q')
        return readInt(word, &e->orientation) && e->orientation >= 0 && e->orientation <= 9;
    if (!readNumber(word, &v))
        return false;
    if (const char *at = std::strchr(kOffsetLetters, c); at && c != '\0') {
        e->offsetMm[static_cast<std::size_t>(at - kOffsetLetters)] = v;
        return true;
    }
    if (c == 'd' && v >= 0)
        e->diameterMm = v;
    else if (c == 'i')
        e->frontAngle = v;
    else if (c == 'j')
        e->backAngle = v;
    else
        return false;
    return true;
}

Error lineError(ErrorCode code, std::uint32_t line, std::size_t column, std::string detail)
{
    return Error{code, line, static_cast<std::uint32_t>(column + 1), std::move(detail), {}};
}

// Reads one line (without its newline) into *e; false with *error on a bad word.
bool parseLine(std::string_view line, std::uint32_t lineNo, ToolEntry *e, bool *empty, Error *error)
{
    const std::size_t semi = line.find(';');
    std::string_view words = line.substr(0, semi);
    if (semi != std::string_view::npos) {
        std::string_view c = line.substr(semi + 1);
        while (!c.empty() && (c.front() == ' ' || c.front() == '\t'))
            c.remove_prefix(1);
        while (!c.empty() && (c.back() == ' ' || c.back() == '\t' || c.back() == '\r'))
            c.remove_suffix(1);
        e->comment = std::string(c);
    }
    bool sawT = false, any = false;
    std::set<char> seen;
    std::size_t i = 0;
    while (i < words.size()) {
        if (std::isspace(static_cast<unsigned char>(words[i]))) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < words.size() && !std::isspace(static_cast<unsigned char>(words[j])))
            ++j;
        const std::string_view word = words.substr(i, j - i);
        const char letter =
            static_cast<char>(std::tolower(static_cast<unsigned char>(word.front())));
        if (!seen.insert(letter).second || !readWord(word, e, &sawT)) {
            *error = lineError(ErrorCode::ToolTableSyntax, lineNo, i, std::string(word));
            return false;
        }
        any = true;
        i = j;
    }
    *empty = !any;
    if (any && !sawT) {
        *error = lineError(ErrorCode::ToolTableSyntax, lineNo, 0, "T");
        return false;
    }
    return true;
}

std::string number(double v)
{
    char buf[64];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::string("0");
}

} // namespace

const ToolEntry *ToolTable::find(int tool) const
{
    for (const ToolEntry &e : tools) {
        if (e.tool == tool)
            return &e;
    }
    return nullptr;
}

ToolEntry *ToolTable::find(int tool)
{
    return const_cast<ToolEntry *>(static_cast<const ToolTable *>(this)->find(tool));
}

bool parseToolTable(std::string_view text, ToolTable *table, Error *error)
{
    ToolTable out;
    std::uint32_t lineNo = 0;
    while (!text.empty()) {
        ++lineNo;
        const std::size_t nl = text.find('\n');
        std::string_view line = text.substr(0, nl);
        text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        ToolEntry e;
        bool empty = true;
        if (!parseLine(line, lineNo, &e, &empty, error))
            return false;
        if (empty)
            continue;
        if (out.find(e.tool)) {
            const std::size_t col = line.find_first_of("Tt");
            *error = lineError(ErrorCode::ToolTableDuplicate, lineNo,
                               col == std::string_view::npos ? 0 : col, std::to_string(e.tool));
            return false;
        }
        out.tools.push_back(std::move(e));
    }
    *table = std::move(out);
    return true;
}

std::string formatToolTable(const ToolTable &table)
{
    std::string out;
    for (const ToolEntry &e : table.tools) {
        out += 'T' + std::to_string(e.tool) + " P" + std::to_string(e.pocket);
        for (std::size_t i = 0; i < e.offsetMm.size(); ++i) {
            if (e.offsetMm[i] != 0)
                out += ' ' + std::string(1, static_cast<char>(kOffsetLetters[i] - 32)) +
                       number(e.offsetMm[i]);
        }
        out += " D" + number(e.diameterMm);
        if (e.frontAngle != 0)
            out += " I" + number(e.frontAngle);
        if (e.backAngle != 0)
            out += " J" + number(e.backAngle);
        if (e.orientation != 0)
            out += " Q" + std::to_string(e.orientation);
        out += " ;" + e.comment + '\n';
    }
    return out;
}

bool readToolTableFile(const std::string &path, ToolTable *table, Error *error, bool missingIsEmpty)
{
    QFile file(QString::fromStdString(path));
    if (!file.exists() && missingIsEmpty) {
        *table = ToolTable{};
        return true;
    }
    if (!file.open(QIODevice::ReadOnly)) {
        *error = Error{ErrorCode::FileOpenFailed, 0, 0, path, {}};
        return false;
    }
    const QByteArray bytes = file.readAll();
    return parseToolTable(
        std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), table, error);
}

bool writeToolTableFile(const std::string &path, const ToolTable &table, Error *error)
{
    QSaveFile file(QString::fromStdString(path));
    const std::string text = formatToolTable(table);
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(text.data(), static_cast<qint64>(text.size())) !=
            static_cast<qint64>(text.size()) ||
        !file.commit()) {
        *error = Error{ErrorCode::FileWriteFailed,
                       0,
                       0,
                       path + kDetailSeparator + file.errorString().toStdString(),
                       {}};
        return false;
    }
    return true;
}

} // namespace frezka::gcode
