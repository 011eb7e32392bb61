#include "gui/grinder/serialmonitor.h"

#include "gui/grinder/portsettings.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QSerialPort>
#include <QSettings>
#include <QVBoxLayout>

namespace frezka::gui {

namespace {
constexpr qint64 kMaxKeptBytes = 4 * 1024 * 1024; // older data leave the view (counted)
}

SerialMonitor::SerialMonitor(QWidget *parent)
    : QWidget(parent)
    , m_hex(new QCheckBox(tr("Hex view"), this))
    , m_view(new QPlainTextEdit(this))
    , m_message(new QLineEdit(this))
    , m_messageHex(new QCheckBox(tr("Hex bytes"), this))
    , m_messagePort(new QComboBox(this))
    , m_status(new QLabel(this))
{
    m_elapsed.start();
    auto *grid = new QGridLayout;
    for (int i = 0; i < kPorts; ++i) {
        m_settings[i] = new PortSettingsRow(false, this);
        m_openButtons[i] = new QPushButton(tr("Open"), this);
        m_openButtons[i]->setObjectName(QStringLiteral("openPort%1").arg(i + 1));
        grid->addWidget(new QLabel(tr("Port %1").arg(i + 1), this), i, 0);
        grid->addWidget(m_settings[i], i, 1);
        grid->addWidget(m_openButtons[i], i, 2);
        connect(m_openButtons[i], &QPushButton::clicked, this, [this, i] { toggle(i); });
        m_messagePort->addItem(tr("to port %1").arg(i + 1));
    }
    m_hex->setObjectName(QStringLiteral("hexView"));
    m_view->setReadOnly(true);
    m_view->setObjectName(QStringLiteral("monitorView"));
    QFont mono(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::Monospace);
    m_view->setFont(mono);
    m_status->setWordWrap(true);
    QSettings settings;
    m_message->setText(
        settings
            .value(QStringLiteral("grinder/monitorMessage"), QStringLiteral("AA 05 00 00 FF 51"))
            .toString());
    m_messageHex->setChecked(settings.value(QStringLiteral("grinder/monitorHex"), true).toBool());
    m_message->setToolTip(tr("Stored message, e.g. AA 05 00 00 FF 51 (K51 ENQ) or Z? as text"));

    auto *clearButton = new QPushButton(tr("Clear"), this);
    auto *captureButton = new QPushButton(tr("Capture to file…"), this);
    auto *sendButton = new QPushButton(tr("Send"), this);
    sendButton->setObjectName(QStringLiteral("sendMessage"));
    auto *viewRow = new QHBoxLayout;
    viewRow->addWidget(m_hex);
    viewRow->addStretch(1);
    viewRow->addWidget(clearButton);
    viewRow->addWidget(captureButton);
    auto *messageRow = new QHBoxLayout;
    messageRow->addWidget(new QLabel(tr("Message:"), this));
    messageRow->addWidget(m_message, 1);
    messageRow->addWidget(m_messageHex);
    messageRow->addWidget(m_messagePort);
    messageRow->addWidget(sendButton);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(grid);
    layout->addLayout(viewRow);
    layout->addWidget(m_view, 1);
    layout->addLayout(messageRow);
    layout->addWidget(m_status);

    connect(m_hex, &QCheckBox::toggled, this, &SerialMonitor::rerender);
    connect(clearButton, &QPushButton::clicked, this, &SerialMonitor::clear);
    connect(captureButton, &QPushButton::clicked, this, &SerialMonitor::capture);
    connect(sendButton, &QPushButton::clicked, this,
            [this] { sendMessage(m_messagePort->currentIndex()); });
}

SerialMonitor::~SerialMonitor()
{
    QSettings settings;
    settings.setValue(QStringLiteral("grinder/monitorMessage"), m_message->text());
    settings.setValue(QStringLiteral("grinder/monitorHex"), m_messageHex->isChecked());
}

bool SerialMonitor::openPort(int index, const grinder::SerialSettings &s)
{
    if (index < 0 || index >= kPorts)
        return false;
    closePort(index);
    m_settings[index]->setSettings(s);
    auto *port = new QSerialPort(this);
    port->setPortName(s.portName);
    if (!port->open(QIODevice::ReadWrite)) {
        m_status->setText(
            tr("Port %1: cannot open %2: %3").arg(index + 1).arg(s.portName, port->errorString()));
        delete port;
        return false;
    }
    port->setBaudRate(s.baud);
    port->setDataBits(static_cast<QSerialPort::DataBits>(s.dataBits));
    port->setParity(s.parity == 'e'   ? QSerialPort::EvenParity
                    : s.parity == 'o' ? QSerialPort::OddParity
                                      : QSerialPort::NoParity);
    port->setStopBits(s.stopBits == 2 ? QSerialPort::TwoStop : QSerialPort::OneStop);
    connect(port, &QSerialPort::readyRead, this, [this, index] { onData(index); });
    connect(port, &QSerialPort::errorOccurred, this,
            [this, index, port](QSerialPort::SerialPortError e) {
                if (e == QSerialPort::NoError || e == QSerialPort::UnsupportedOperationError ||
                    e == QSerialPort::TimeoutError)
                    return; // a pty refuses DTR/RTS: not a failure
                m_status->setText(tr("Port %1: %2").arg(index + 1).arg(port->errorString()));
            });
    m_ports[index] = port;
    m_openButtons[index]->setText(tr("Close"));
    m_settings[index]->setEnabled(false);
    m_status->setText(
        tr("Port %1: watching %2 at %3 Bd.").arg(index + 1).arg(s.portName).arg(s.baud));
    return true;
}

void SerialMonitor::closePort(int index)
{
    if (index < 0 || index >= kPorts || !m_ports[index])
        return;
    m_ports[index]->close();
    m_ports[index]->deleteLater();
    m_ports[index] = nullptr;
    m_openButtons[index]->setText(tr("Open"));
    m_settings[index]->setEnabled(true);
}

bool SerialMonitor::isPortOpen(int index) const
{
    return index >= 0 && index < kPorts && m_ports[index];
}

void SerialMonitor::toggle(int index)
{
    if (isPortOpen(index))
        closePort(index);
    else
        openPort(index, m_settings[index]->settings());
}

void SerialMonitor::onData(int index)
{
    append({index, m_elapsed.elapsed(), false, m_ports[index]->readAll()});
}

void SerialMonitor::append(const Chunk &chunk)
{
    m_chunks.push_back(chunk);
    m_keptBytes += chunk.bytes.size();
    m_view->appendPlainText(render(chunk));
    if (m_keptBytes <= kMaxKeptBytes)
        return;
    while (m_keptBytes > kMaxKeptBytes / 2 && !m_chunks.empty()) {
        m_keptBytes -= m_chunks.front().bytes.size();
        m_droppedBytes += m_chunks.front().bytes.size();
        m_chunks.erase(m_chunks.begin());
    }
    m_status->setText(tr("%1 older bytes left the view; capture to a file to keep everything.")
                          .arg(m_droppedBytes));
    rerender();
}

QString SerialMonitor::render(const Chunk &chunk) const
{
    QString text;
    if (m_hex->isChecked()) {
        text = QString::fromLatin1(chunk.bytes.toHex(' ').toUpper());
    } else {
        for (char c : chunk.bytes) {
            const auto byte = static_cast<unsigned char>(c);
            if (byte >= 0x20 && byte < 0x7F)
                text += QLatin1Char(c);
            else
                text += QStringLiteral("<%1>").arg(byte, 2, 16, QLatin1Char('0')).toUpper();
        }
    }
    return QStringLiteral("%1 %2%3  %4")
        .arg(chunk.ms / 1000.0, 9, 'f', 3)
        .arg(chunk.sent ? QStringLiteral("->") : QStringLiteral("<-"))
        .arg(chunk.port + 1)
        .arg(text);
}

void SerialMonitor::rerender()
{
    QStringList lines;
    for (const Chunk &chunk : m_chunks)
        lines << render(chunk);
    m_view->setPlainText(lines.join(QLatin1Char('\n')));
}

QString SerialMonitor::viewText() const
{
    return m_view->toPlainText();
}

void SerialMonitor::setHexView(bool hex)
{
    m_hex->setChecked(hex);
}

void SerialMonitor::clear()
{
    m_chunks.clear();
    m_keptBytes = 0;
    m_view->clear();
}

void SerialMonitor::setMessage(const QString &message, bool hex)
{
    m_message->setText(message);
    m_messageHex->setChecked(hex);
}

bool SerialMonitor::messageBytes(QByteArray &bytes, QString &error) const
{
    if (!m_messageHex->isChecked()) {
        bytes = m_message->text().toLatin1();
        return !bytes.isEmpty();
    }
    const QString digits = m_message->text().remove(QLatin1Char(' '));
    bool ok = digits.size() % 2 == 0 && !digits.isEmpty();
    for (int i = 0; ok && i < digits.size(); i += 2) {
        const int value = digits.mid(i, 2).toInt(&ok, 16);
        bytes.append(char(value));
    }
    if (!ok)
        error = tr("The message \"%1\" is not hex bytes (e.g. AA 05 00 00 FF 51).")
                    .arg(m_message->text());
    return ok;
}

bool SerialMonitor::sendMessage(int index)
{
    if (!isPortOpen(index)) {
        m_status->setText(tr("Port %1 is not open.").arg(index + 1));
        return false;
    }
    QByteArray bytes;
    QString error;
    if (!messageBytes(bytes, error)) {
        m_status->setText(error.isEmpty() ? tr("The message is empty.") : error);
        return false;
    }
    if (m_ports[index]->write(bytes) != bytes.size()) {
        m_status->setText(tr("Port %1: the message could not be sent: %2")
                              .arg(index + 1)
                              .arg(m_ports[index]->errorString()));
        return false;
    }
    append({index, m_elapsed.elapsed(), true, bytes});
    return true;
}

void SerialMonitor::capture()
{
    // FOLLOWER numbered its captures FOLLOVER.000 to .999; suggest the next free number.
    QString suggestion;
    do {
        suggestion = QDir::home().filePath(
            QStringLiteral("capture-%1.txt").arg(m_captureNumber++, 3, 10, QLatin1Char('0')));
    } while (QFile::exists(suggestion) && m_captureNumber < 1000);
    const QString path =
        m_chooser ? m_chooser(suggestion)
                  : QFileDialog::getSaveFileName(this, tr("Capture to file"), suggestion);
    if (!path.isEmpty())
        captureTo(path);
}

bool SerialMonitor::captureTo(const QString &path)
{
    QSaveFile file(path);
    const QByteArray text = (viewText() + QLatin1Char('\n')).toUtf8();
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size() || !file.commit()) {
        m_status->setText(tr("Cannot write %1: %2").arg(path, file.errorString()));
        return false;
    }
    m_status->setText(tr("Captured %1 lines to %2.").arg(m_chunks.size()).arg(path));
    return true;
}

QString SerialMonitor::statusText() const
{
    return m_status->text();
}

} // namespace frezka::gui
