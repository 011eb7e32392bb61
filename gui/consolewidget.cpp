#include "consolewidget.h"

#include "driver/link/tracerecorder.h"

#include <QCheckBox>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace frezka::gui {

ConsoleWidget::ConsoleWidget(QWidget *parent)
    : QWidget(parent)
{
    m_view = new QPlainTextEdit(this);
    m_view->setObjectName(QStringLiteral("consoleLog"));
    m_view->setReadOnly(true);
    m_view->setMaximumBlockCount(20000);
    m_view->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_view->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_hexBox = new QCheckBox(this);
    m_hexBox->setObjectName(QStringLiteral("consoleHex"));
    connect(m_hexBox, &QCheckBox::toggled, this, &ConsoleWidget::setHex);
    m_pollBox = new QCheckBox(this);
    m_pollBox->setObjectName(QStringLiteral("consolePolls"));
    connect(m_pollBox, &QCheckBox::toggled, this, &ConsoleWidget::setShowPolls);
    m_save = new QPushButton(this);
    // The serial trace first (both ways, timed, ASCII and hex: what a report of a problem
    // needs, docs/serial-trace.md), the log as shown as the other choice.
    connect(m_save, &QPushButton::clicked, this, [this] {
        const QString traceFilter = tr("Serial trace (*.trace)");
        QString chosen;
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Save log"), QString(),
            traceFilter + QStringLiteral(";;") + tr("Console log as shown (*.txt *.log)"), &chosen);
        if (path.isEmpty())
            return;
        QString error;
        const bool saved = chosen == traceFilter
                               ? driver::TraceRecorder::session().save(path, &error)
                               : saveTo(path, &error);
        if (!saved)
            QMessageBox::warning(this, tr("Save log"), error);
    });
    m_clear = new QPushButton(this);
    connect(m_clear, &QPushButton::clicked, this, [this] {
        m_entries.clear();
        m_pending = 0;
        m_view->clear();
    });
    m_line = new QLineEdit(this);
    m_line->setObjectName(QStringLiteral("consoleLine"));
    m_send = new QPushButton(this);
    auto send = [this] {
        const QString text = m_line->text().trimmed();
        if (text.isEmpty())
            return;
        m_line->clear();
        emit manualLineEntered(text);
    };
    connect(m_line, &QLineEdit::returnPressed, this, send);
    connect(m_send, &QPushButton::clicked, this, send);

    auto *tools = new QHBoxLayout;
    tools->addWidget(m_hexBox);
    tools->addWidget(m_pollBox);
    tools->addStretch();
    tools->addWidget(m_clear);
    tools->addWidget(m_save);
    auto *input = new QHBoxLayout;
    input->addWidget(m_line, 1);
    input->addWidget(m_send);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(tools);
    layout->addWidget(m_view, 1);
    layout->addLayout(input);

    m_flushTimer.setInterval(100);
    m_flushTimer.setSingleShot(true);
    connect(&m_flushTimer, &QTimer::timeout, this, &ConsoleWidget::flush);
    retranslate();
}

void ConsoleWidget::append(LogDirection direction, const QByteArray &bytes)
{
    // Polls: position (P, PF, P4), flags (F), inputs (I1, I2), status (SR6), the link's own
    // index and last-reply queries (@, >, docs/gve-protocol.md §8), and the reply that
    // follows one (the link is half duplex, so the next received line answers it).
    static const QRegularExpression kPoll(
        QStringLiteral("^!?[0-7]?(P|PF|P4|F|I1|I2|SR6|@|>)(,[0-9A-F]{2})?\\r?$"));
    bool poll = false;
    if (direction == LogDirection::Sent) {
        poll = kPoll.match(QString::fromLatin1(bytes).trimmed()).hasMatch();
        m_lastSentWasPoll = poll;
    } else if (direction == LogDirection::Received) {
        poll = std::exchange(m_lastSentWasPoll, false);
    }
    m_entries.push_back({QDateTime::currentDateTime(), direction, bytes, poll});
    if (m_entries.size() > kKeep)
        m_entries.pop_front();
    m_pending = std::min(m_pending + 1, m_entries.size());
    if (!m_flushTimer.isActive())
        m_flushTimer.start();
}

QString ConsoleWidget::formatEntry(const LogEntry &e) const
{
    static const char *kPrefix[] = {"> ", "< ", "# ", "! "};
    QString body;
    if (m_hex && (e.direction == LogDirection::Sent || e.direction == LogDirection::Received)) {
        body = QString::fromLatin1(e.bytes.toHex(' ').toUpper());
    } else if (e.direction == LogDirection::Sent || e.direction == LogDirection::Received) {
        body = QString::fromUtf8(e.bytes); // the wire's bytes: line ends shown as such
        body.replace(QLatin1Char('\r'), QStringLiteral("\\r"));
        body.replace(QLatin1Char('\n'), QStringLiteral("\\n"));
    } else {
        // A message of several lines: each further line indented under the first.
        body = QString::fromUtf8(e.bytes);
        body.remove(QLatin1Char('\r'));
        body.replace(QLatin1Char('\n'), QStringLiteral("\n               "));
    }
    return e.time.toString(QStringLiteral("HH:mm:ss.zzz ")) +
           QLatin1String(kPrefix[int(e.direction)]) + body;
}

void ConsoleWidget::flush()
{
    if (m_pending == 0)
        return;
    QStringList lines;
    const std::size_t from = m_entries.size() - m_pending;
    const std::size_t shown = std::min<std::size_t>(m_pending, 20000);
    for (std::size_t i = m_entries.size() - shown; i < m_entries.size(); ++i) {
        if (m_showPolls || !m_entries[i].poll)
            lines << formatEntry(m_entries[i]);
    }
    if (lines.isEmpty()) {
        m_pending = 0;
        return;
    }
    Q_UNUSED(from);
    m_pending = 0;
    m_view->appendPlainText(lines.join(QLatin1Char('\n')));
}

void ConsoleWidget::setHex(bool hex)
{
    if (hex == m_hex)
        return;
    m_hex = hex;
    m_hexBox->setChecked(hex);
    rebuildView();
}

void ConsoleWidget::setShowPolls(bool show)
{
    if (show == m_showPolls)
        return;
    m_showPolls = show;
    m_pollBox->setChecked(show);
    rebuildView();
}

void ConsoleWidget::rebuildView()
{
    m_view->clear();
    m_pending = std::min<std::size_t>(m_entries.size(), 20000);
    flush();
}

bool ConsoleWidget::saveTo(const QString &path, QString *error) const
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        if (error)
            *error = tr("Cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    for (const auto &e : m_entries)
        f.write(formatEntry(e).toUtf8() + '\n');
    if (!f.flush()) {
        if (error)
            *error = tr("Cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

void ConsoleWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ConsoleWidget::retranslate()
{
    m_hexBox->setText(tr("Hex"));
    m_pollBox->setText(tr("Polls"));
    m_pollBox->setToolTip(tr("Also show the periodic position and status polls"));
    m_save->setText(tr("Save log…"));
    m_clear->setText(tr("Clear"));
    m_send->setText(tr("Send"));
    m_line->setPlaceholderText(
        tr("G-code (e.g. G0 X10) or a raw unit command (e.g. !0PF), Enter sends"));
}

} // namespace frezka::gui
