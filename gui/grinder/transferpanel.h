#pragma once
// KCOMM's job: Controller -> PC (shows header and length, Save) and PC -> Controller (file,
// editable 16-character header, send), with a progress bar showing bytes and time left, the
// inner-block check, the post-load "no prg set" hint and a trace of every message.

#include "driver/grinder/transfersession.h"

#include <QWidget>

#include <functional>
#include <optional>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;

namespace frezka::gui {

class TransferPanel : public QWidget
{
    Q_OBJECT
public:
    enum class FileChoice { SaveReceived, OpenToSend };
    // Returns the chosen path or an empty string. The default opens a QFileDialog; tests set
    // their own so no modal dialog appears.
    using FileChooser = std::function<QString(FileChoice choice, const QString &suggestion)>;

    TransferPanel(grinder::Clock &clock, QWidget *parent = nullptr);

    // nullptr when disconnected; `baud` for the time-left estimate before a rate is measured.
    void setSession(grinder::TransferSession *session, int baud = 9600);
    void setLinkUp(bool up);
    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }
    void updateEnabled();

    // The actions behind the buttons (also for tests and scripts).
    bool receive();                         // Controller -> PC
    bool saveReceived(const QString &path); // write the received data, byte for byte
    bool openFileToSend(const QString &path);
    void setHeaderText(const QString &text);
    bool send(); // PC -> Controller
    // Sends `data` (not from a file: the HEDIT editor) under `label` with `header`.
    bool sendData(const QByteArray &data, const QString &label, const QString &header,
                  grinder::Family family);
    grinder::Header receivedHeader() const { return m_received.header; }
    void cancel(); // stop the transfer in progress
    QByteArray receivedData() const { return m_received.data; }
    QString statusText() const;
    // The failure banner's text; empty while it is hidden.
    QString failureText() const;
    // Data received from the controller and not yet saved to a file.
    bool hasUnsavedData() const { return !m_received.data.isEmpty() && !m_receivedSaved; }
    void setSendAnyway(bool on);
    // What the header becomes on the controller (Czech letters mapped) or why it cannot.
    QString headerNote() const;
    QString receivedHeaderText() const;

signals:
    void transferFinished(const frezka::grinder::TransferResult &result);

private:
    void buildLayout();
    void onProgress(qint64 done, qint64 total);
    void onFinished(const grinder::TransferResult &result);
    void chooseSaveFile();
    void chooseSendFile();
    QString chooseFile(FileChoice choice, const QString &suggestion);
    void appendLog(const QString &line);
    void showFailure(const QString &text);
    void clearReceived();

    grinder::Clock &m_clock;
    grinder::TransferSession *m_session = nullptr;
    bool m_linkUp = false;
    int m_baud = 9600;
    FileChooser m_chooser;
    void updateHeaderNote();

    grinder::TransferResult m_received;
    grinder::Family m_receivedFamily = grinder::Family::K51;
    std::optional<grinder::Family> m_toSendFamily; // a Frezka grinder file names its system
    bool m_receivedSaved = false;
    QByteArray m_toSend;
    QString m_toSendPath;
    std::int64_t m_startUs = 0;

    QPushButton *m_receiveButton;
    QLabel *m_receivedHeader;
    QLabel *m_receivedLength;
    QLabel *m_receivedBlocks;
    QPushButton *m_saveButton;
    QLineEdit *m_sendFile;
    QPushButton *m_chooseButton;
    QLabel *m_sendInfo;
    QLineEdit *m_header;
    QLabel *m_headerNote;
    QPushButton *m_sendButton;
    QPushButton *m_cancelButton;
    QProgressBar *m_progress;
    QLabel *m_progressText;
    QLabel *m_status;
    QLabel *m_banner;
    QCheckBox *m_sendAnyway;
    QLabel *m_hint;
    QPlainTextEdit *m_log;
};

} // namespace frezka::gui
