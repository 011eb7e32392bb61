#include "programtext.h"

#include <QStringList>

#include <cstring>

namespace frezka::session {

ProgramText::ProgramText(QByteArray data, const std::function<void(qint64, qint64)> &progress,
                         const std::atomic_bool *cancel)
    : m_data(std::move(data))
{
    const qint64 n = m_data.size();
    const char *p = m_data.constData();
    m_starts.reserve(std::size_t(n / 24 + 1));
    qint64 pos = 0;
    constexpr qint64 kChunk = 1 << 22;
    while (pos < n) {
        m_starts.push_back(pos);
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
    const qint64 start = m_starts[std::size_t(index)];
    qint64 end = index + 1 < lineCount() ? m_starts[std::size_t(index) + 1] : m_data.size();
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
