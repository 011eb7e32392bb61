#pragma once
// ConsoleWidget: the command/reply log (ASCII or hex, saveable) and a line for manual G-code or
// raw unit commands ("!0PF"). Log lines are batched and shown every 100 ms so a streaming link
// cannot flood the event loop; the last kKeep entries are kept for the view and for saving.

#include <QByteArray>
#include <QDateTime>
#include <QTimer>
#include <QWidget>

#include <deque>

class QCheckBox;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;

namespace frezka::gui {

enum class LogDirection { Sent, Received, Info, Error };

struct LogEntry
{
    QDateTime time;
    LogDirection direction = LogDirection::Info;
    QByteArray bytes;
    bool poll = false; // a status/position poll or its reply (hidden unless "Polls" is on)
};

class ConsoleWidget : public QWidget
{
    Q_OBJECT

public:
    static constexpr std::size_t kKeep = 100000;
    explicit ConsoleWidget(QWidget *parent = nullptr);

    void append(LogDirection direction, const QByteArray &bytes);
    void appendInfo(const QString &text) { append(LogDirection::Info, text.toUtf8()); }
    void appendError(const QString &text) { append(LogDirection::Error, text.toUtf8()); }
    void setHex(bool hex);
    bool isHex() const { return m_hex; }
    // Shows the periodic position/status polls and their replies too (off by default).
    void setShowPolls(bool show);
    // Writes the kept log as text (in the current view mode); false and a message on failure.
    bool saveTo(const QString &path, QString *error = nullptr) const;
    const std::deque<LogEntry> &entries() const { return m_entries; }
    QString formatEntry(const LogEntry &e) const;
    // Flushes pending lines into the view now (tests).
    void flush();

signals:
    void manualLineEntered(const QString &line);

protected:
    void changeEvent(QEvent *event) override;

private:
    void rebuildView();
    void retranslate();

    std::deque<LogEntry> m_entries;
    std::size_t m_pending = 0; // entries not yet shown
    bool m_hex = false;
    bool m_showPolls = false;
    bool m_lastSentWasPoll = false;
    QTimer m_flushTimer;
    QPlainTextEdit *m_view;
    QCheckBox *m_hexBox, *m_pollBox;
    QPushButton *m_save, *m_clear, *m_send;
    QLineEdit *m_line;
};

} // namespace frezka::gui
