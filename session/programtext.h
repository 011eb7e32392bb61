#pragma once
// ProgramText: the raw program file with an index of line starts, so that a listing of millions
// of lines costs one buffer plus 4-8 bytes per line. Immutable once built; shared by pointer.

#include <QByteArray>
#include <QString>

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace frezka::session {

class ProgramText
{
public:
    ProgramText() = default;
    // Builds the line index over data. progress(doneBytes, totalBytes); cancel aborts.
    explicit ProgramText(QByteArray data, const std::function<void(qint64, qint64)> &progress = {},
                         const std::atomic_bool *cancel = nullptr);

    int lineCount() const { return int(m_starts32.size() + m_starts64.size()); }
    // Line by 0-based index, without its end-of-line characters.
    QString line(int index) const;
    const QByteArray &data() const { return m_data; }
    // Bytes the line index holds (its capacity), for the memory benchmark and its test.
    std::size_t indexBytes() const
    {
        return m_starts32.capacity() * sizeof(std::uint32_t) +
               m_starts64.capacity() * sizeof(qint64);
    }

    // The comment of a 1-based line: the text of its ( ) comments, or after ';' (0 or out of
    // range: empty), for an operator stop ("M0 (check the slot depth)").
    QString comment(int line) const;

private:
    qint64 start(int index) const
    {
        return m_starts64.empty() ? qint64(m_starts32[std::size_t(index)])
                                  : m_starts64[std::size_t(index)];
    }

    QByteArray m_data;
    // Where each line starts: 32 bits in a file under 4 GB (issue 17: 20 MB less at 5 M lines),
    // else 64; one of the two is empty.
    std::vector<std::uint32_t> m_starts32;
    std::vector<qint64> m_starts64;
};

} // namespace frezka::session
