#include "programtext.h"

#include <QStringList>

#include <cstring>
#include <limits>

namespace frezka::session {

ProgramText::ProgramText(QByteArray data, const std::function<void(qint64, qint64)> &progress,
                         const std::atomic_bool *cancel)
    : m_data(std::move(data))
{
    const qint64 n = m_data.size();
    const char *p = m_data.constData();
    const bool narrow = n <= qint64(std::numeric_limits<std::uint32_t>::max());
    // The lines counted first (a memchr walk, a few per cent of the indexing): the index is
    // reserved at its size, not grown by doubling past it (at 5 M lines that held 38 MB more).
    std::size_t lines = 0;
    for (const char *q = p, *e = p + n; q < e; ++lines) {
        const void *nl = std::memchr(q, '\n', std::size_t(e - q));
        q = nl ? static_cast<const char *>(nl) + 1 : e;
    }
    if (narrow)
        m_starts32.reserve(lines);
    else
        m_starts64.reserve(lines);
    qint64 pos = 0;
    constexpr qint64 kChunk = 1 << 22;
    while (pos < n) {
        if (narrow)
            m_starts32.push_back(std::uint32_t(pos));
        else
            m_starts64.push_back(pos);
        const void *nl = std::memchr(p + pos, '\n', std::size_t(n - pos));
        if (!nl)
            break;
        const qint64 next = static_cast<const char *>(nl) - p + 1;
        if (progress && (next / kChunk) != (pos / kChunk)) {
            progress(next, n);
            if (cancel && cancel->load())
                return;
        }
        pos = next;
    }
}

QString ProgramText::line(int index) const
{
    if (index < 0 || index >= lineCount())
        return {};
    const qint64 start = this->start(index);
    qint64 end = index + 1 < lineCount() ? this->start(index + 1) : m_data.size();
    while (end > start && (m_data[end - 1] == '\n' || m_data[end - 1] == '\r'))
        --end;
    return QString::fromUtf8(m_data.constData() + start, end - start);
}

QString ProgramText::comment(int line) const
{
    if (line < 1 || line > lineCount())
        return {};
    const QString text = this->line(line - 1);
    QStringList parts;
    qsizetype i = 0;
    while (i < text.size()) {
        if (text[i] == QLatin1Char(';')) {
            parts << text.mid(i + 1).trimmed();
            break;
        }
        if (text[i] == QLatin1Char('(')) {
            const qsizetype end = text.indexOf(QLatin1Char(')'), i + 1);
            parts << text.mid(i + 1, end < 0 ? -1 : end - i - 1).trimmed();
            if (end < 0)
                break;
            i = end;
        }
        ++i;
    }
    parts.removeAll(QString());
    return parts.join(QStringLiteral("; "));
}

} // namespace frezka::session
