#pragma once
// Serial monitor (the FOLLOWER tool's job): watches one or two ports at once, shows what
// arrives as ASCII or hex with the port and time, captures the view to a file and sends a
// stored message (hex bytes or text) to either port.

#include "driver/grinder/transport.h"

#include <QElapsedTimer>
#include <QWidget>

#include <array>
#include <functional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QSerialPort;

namespace frezka::gui {

class PortSettingsRow;

class SerialMonitor : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kPorts = 2;
    // Returns a file path to capture to, or empty; tests set one to avoid the modal dialog.
    using FileChooser = std::function<QString(const QString &suggestion)>;

    explicit SerialMonitor(QWidget *parent = nullptr);
    ~SerialMonitor() override;

    bool openPort(int index, const grinder::SerialSettings &settings);
    void closePort(int index);
    bool isPortOpen(int index) const;
    void setHexView(bool hex);
    QString viewText() const;
    void clear();
    // The stored message: hex bytes ("AA 05 00 00 FF 51") or text.
    void setMessage(const QString &message, bool hex);
    bool sendMessage(int index);
    bool captureTo(const QString &path);
    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }
    QString statusText() const;

private:
    struct Chunk
    {
        int port;
        qint64 ms;
        bool sent;
        QByteArray bytes;
    };
    void onData(int index);
    void append(const Chunk &chunk);
    QString render(const Chunk &chunk) const;
    void rerender();
    void toggle(int index);
    void capture();
    bool messageBytes(QByteArray &bytes, QString &error) const;

    std::array<QSerialPort *, kPorts> m_ports{};
    std::array<PortSettingsRow *, kPorts> m_settings{};
    std::array<QPushButton *, kPorts> m_openButtons{};
    std::vector<Chunk> m_chunks;
    qint64 m_keptBytes = 0;
    qint64 m_droppedBytes = 0;
    QElapsedTimer m_elapsed;
    FileChooser m_chooser;
    int m_captureNumber = 0;
    QCheckBox *m_hex;
    QPlainTextEdit *m_view;
    QLineEdit *m_message;
    QCheckBox *m_messageHex;
    QComboBox *m_messagePort;
    QLabel *m_status;
};

} // namespace frezka::gui
