#pragma once
// ProgramText: the raw program file with an index of line starts, so that a listing of millions
// of lines costs one buffer plus 4-8 bytes per line. Immutable once built; shared by pointer.

#include <QByteArray>
#include <QString>

#include <atomic>
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

    int lineCount() const { return int(m_starts.size()); }
    // Line by 0-based index, without its end-of-line characters.
    QString line(int index) const;
    const QByteArray &data() const { return m_data; }

    // The comment of a 1-based line: the text of its ( ) comments, or after ';' (0 or out of
    // range: empty), for an operator stop ("M0 (check the slot depth)").
    QString comment(int line) const;

private:
    QByteArray m_data;
    std::vector<qint64> m_starts;
};

} // namespace frezka::session
