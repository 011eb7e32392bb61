// Filling in and translating the messages of gcode/error.h (the table is in error.cpp).
#include "error.h"

#include <QCoreApplication>
#include <QStringList>

#include <string>
#include <vector>

namespace frezka::gcode {

namespace {

// Replaces %1..%9 in one pass (a value that contains "%2" is not filled again).
char16_t charAt(const std::string &s, std::size_t i)
{
    return static_cast<unsigned char>(s[i]);
}

char16_t charAt(const QString &s, std::size_t i)
{
    return s.at(static_cast<qsizetype>(i)).unicode();
}

template<typename Str, typename Parts>
Str fillArgs(const Str &text, const Parts &parts)
{
    Str out;
    const auto n = static_cast<std::size_t>(text.size());
    for (std::size_t i = 0; i < n; ++i) {
        const char16_t next = i + 1 < n ? charAt(text, i + 1) : 0;
        if (charAt(text, i) == '%' && next >= '1' && next <= '9') {
            const auto k = static_cast<std::size_t>(next - '1');
            if (k < static_cast<std::size_t>(parts.size())) {
                out += parts[static_cast<decltype(parts.size())>(k)];
                ++i;
                continue;
            }
        }
        out += text[static_cast<decltype(text.size())>(i)];
    }
    return out;
}

std::vector<std::string> detailParts(const std::string &detail)
{
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (;;) {
        const std::size_t end = detail.find(kDetailSeparator, start);
        parts.push_back(detail.substr(start, end - start));
        if (end == std::string::npos)
            return parts;
        start = end + 1;
    }
}

} // namespace

std::string englishMessage(const Error &error)
{
    const std::vector<std::string> parts = detailParts(error.detail);
    std::string text = fillArgs(std::string(errorTemplate(error.code)), parts);
    text += ". ";
    text += fillArgs(std::string(errorHint(error.code)), parts);
    return text;
}

QString translatedMessage(const Error &error)
{
    const QString text = QCoreApplication::translate("frezka::gcode", errorTemplate(error.code));
    QStringList parts;
    for (const std::string &p : detailParts(error.detail))
        parts << QString::fromStdString(p);
    return fillArgs(text, parts) + QStringLiteral(". ") +
           fillArgs(QCoreApplication::translate("frezka::gcode", errorHint(error.code)), parts);
}

QString formatError(const QString &file, const Error &error)
{
    QString message = translatedMessage(error);
    if (severity(error.code) == Severity::Warning)
        message = QCoreApplication::translate("frezka::gcode", "warning: ") + message;
    else if (severity(error.code) == Severity::Note)
        message = QCoreApplication::translate("frezka::gcode", "note: ") + message;
    const QString where = error.file.empty() ? file : QString::fromStdString(error.file);
    if (error.line == 0)
        return QStringLiteral("%1: %2").arg(where, message);
    return QStringLiteral("%1:%2:%3: %4").arg(where).arg(error.line).arg(error.column).arg(message);
}

} // namespace frezka::gcode
