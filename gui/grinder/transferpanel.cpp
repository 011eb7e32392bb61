#include "gui/grinder/transferpanel.h"

#include "driver/grinder/controllerheader.h"
#include "driver/grinder/grinderfile.h"

#include <QCheckBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSaveFile>
#include <QTime>
#include <QVBoxLayout>

namespace frezka::gui {

using namespace frezka::grinder;

namespace {
QString formatSeconds(double seconds)
{
    const int s = int(seconds + 0.5);
    return QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}
} // namespace

TransferPanel::TransferPanel(Clock &clock, QWidget *parent)
    : QWidget(parent)
    , m_clock(clock)
    , m_receiveButton(new QPushButton(tr("Controller → PC"), this))
    , m_receivedHeader(new QLabel(this))
    , m_receivedLength(new QLabel(this))
    , m_receivedBlocks(new QLabel(this))
    , m_saveButton(new QPushButton(tr("Save…"), this))
    , m_sendFile(new QLineEdit(this))
    , m_chooseButton(new QPushButton(tr("Choose file…"), this))
    , m_sendInfo(new QLabel(this))
    , m_header(new QLineEdit(this))
    , m_headerNote(new QLabel(this))
    , m_sendButton(new QPushButton(tr("PC → Controller"), this))
    , m_cancelButton(new QPushButton(tr("Cancel"), this))
    , m_progress(new QProgressBar(this))
    , m_progressText(new QLabel(this))
    , m_status(new QLabel(this))
    , m_banner(new QLabel(this))
    , m_sendAnyway(new QCheckBox(tr("Send anyway"), this))
    , m_hint(new QLabel(this))
    , m_log(new QPlainTextEdit(this))
{
    m_receiveButton->setObjectName(QStringLiteral("receiveButton"));
    m_saveButton->setObjectName(QStringLiteral("saveButton"));
    m_chooseButton->setObjectName(QStringLiteral("chooseButton"));
    m_sendButton->setObjectName(QStringLiteral("sendButton"));
    m_header->setObjectName(QStringLiteral("header"));
    m_status->setObjectName(QStringLiteral("transferStatus"));
    m_hint->setObjectName(QStringLiteral("hint"));
    m_receiveButton->setToolTip(tr("Ask the controller for its programs (DEJ) and receive them."));
    m_sendButton->setToolTip(tr("Send the chosen file to the controller unchanged."));
    m_cancelButton->setObjectName(QStringLiteral("cancelButton"));
    m_header->setMaxLength(int(kHeaderSize));
    // The controller shows printable ASCII only: the note says what Czech letters become.
    m_headerNote->setObjectName(QStringLiteral("headerNote"));
    m_headerNote->setWordWrap(true);
    m_headerNote->setVisible(false);
    connect(m_header, &QLineEdit::textChanged, this, &TransferPanel::updateHeaderNote);
    m_header->setPlaceholderText(tr("16 characters shown on the controller"));
    m_sendFile->setReadOnly(true);
    m_sendFile->setPlaceholderText(tr("No file chosen"));
    m_receivedBlocks->setWordWrap(true);
    m_sendInfo->setWordWrap(true);
    m_status->setWordWrap(true);
    m_hint->setWordWrap(true);
    m_hint->setVisible(false);
    m_banner->setObjectName(QStringLiteral("failureBanner"));
    m_banner->setWordWrap(true);
    m_banner->setVisible(false);
    m_banner->setStyleSheet(QStringLiteral(
        "QLabel { background: #fde0e0; color: #8b0000; padding: 6px; font-weight: bold; }"));
    m_sendAnyway->setObjectName(QStringLiteral("sendAnyway"));
    m_sendAnyway->setToolTip(
        tr("Send a file whose inner blocks have a wrong checksum, or whose length this "
           "controller reported itself. Only for data the controller gave you."));
    m_progressText->setWordWrap(true);
    m_hint->setStyleSheet(QStringLiteral("QLabel { background: #fff4c2; padding: 6px; }"));
    m_log->setObjectName(QStringLiteral("transferLog"));
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(2000);
    m_saveButton->setEnabled(false);

    buildLayout();

    connect(m_receiveButton, &QPushButton::clicked, this, &TransferPanel::receive);
    connect(m_saveButton, &QPushButton::clicked, this, &TransferPanel::chooseSaveFile);
    connect(m_chooseButton, &QPushButton::clicked, this, &TransferPanel::chooseSendFile);
    connect(m_sendButton, &QPushButton::clicked, this, &TransferPanel::send);
    connect(m_cancelButton, &QPushButton::clicked, this, &TransferPanel::cancel);
    updateEnabled();
}

void TransferPanel::buildLayout()
{
    auto *fromBox = new QGroupBox(tr("Controller → PC"), this);
    auto *fromForm = new QFormLayout(fromBox);
    fromForm->addRow(m_receiveButton);
    fromForm->addRow(tr("Header:"), m_receivedHeader);
    fromForm->addRow(tr("Length:"), m_receivedLength);
    fromForm->addRow(tr("Inner blocks:"), m_receivedBlocks);
    fromForm->addRow(m_saveButton);

    auto *toBox = new QGroupBox(tr("PC → Controller"), this);
    auto *toForm = new QFormLayout(toBox);
    auto *fileRow = new QHBoxLayout;
    fileRow->addWidget(m_sendFile, 1);
    fileRow->addWidget(m_chooseButton);
    toForm->addRow(tr("File:"), fileRow);
    toForm->addRow(QString(), m_sendInfo);
    toForm->addRow(tr("Header:"), m_header);
    toForm->addRow(QString(), m_headerNote);
    toForm->addRow(m_sendAnyway);
    toForm->addRow(m_sendButton);

    auto *boxes = new QHBoxLayout;
    boxes->addWidget(fromBox, 1);
    boxes->addWidget(toBox, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(boxes);
    auto *progressRow = new QHBoxLayout;
    progressRow->addWidget(m_progress, 1);
    progressRow->addWidget(m_cancelButton);
    layout->addLayout(progressRow);
    layout->addWidget(m_progressText);
    layout->addWidget(m_status);
    layout->addWidget(m_banner);
    layout->addWidget(m_hint);
    layout->addWidget(new QLabel(tr("Messages:"), this));
    layout->addWidget(m_log, 1);
}

void TransferPanel::setSession(TransferSession *session, int baud)
{
    m_baud = baud;
    if (m_session)
        disconnect(m_session, nullptr, this, nullptr);
    m_session = session;
    if (m_session) {
        connect(m_session, &TransferSession::progressed, this, &TransferPanel::onProgress);
        connect(m_session, &TransferSession::finished, this, &TransferPanel::onFinished);
        connect(m_session, &TransferSession::traced, this, &TransferPanel::appendLog);
    }
    updateEnabled();
}

void TransferPanel::setLinkUp(bool up)
{
    m_linkUp = up;
    updateEnabled();
}

void TransferPanel::updateEnabled()
{
    const bool ready = m_session && m_linkUp && !m_session->isBusy();
    m_receiveButton->setEnabled(ready && familyInfo(m_session->family()).saves);
    // ANC messages carry no header (ANCLOAD sent none): the field is off, not ignored silently.
    const bool hasHeader = !m_session || m_session->family() != Family::Anc;
    m_header->setEnabled(hasHeader);
    m_header->setToolTip(hasHeader ? QString()
                                   : tr("ANC messages carry no header; nothing typed here would "
                                        "be sent."));
    m_sendButton->setEnabled(ready && !m_toSend.isEmpty());
    m_saveButton->setEnabled(!m_received.data.isEmpty());
    m_cancelButton->setEnabled(m_session && m_session->isBusy() &&
                               m_session->lastResult().operation != Operation::Ping);
}

void TransferPanel::cancel()
{
    if (m_session && m_session->isBusy())
        m_session->cancel();
}

QString TransferPanel::statusText() const
{
    return m_status->text();
}

QString TransferPanel::receivedHeaderText() const
{
    return m_receivedHeader->text();
}

QString TransferPanel::failureText() const
{
    return m_banner->isHidden() ? QString() : m_banner->text();
}

void TransferPanel::setSendAnyway(bool on)
{
    m_sendAnyway->setChecked(on);
}

void TransferPanel::showFailure(const QString &text)
{
    m_banner->setText(text);
    m_banner->setVisible(true);
}

// Data of an earlier transfer are never offered once a new one starts.
void TransferPanel::clearReceived()
{
    m_received = TransferResult();
    m_receivedSaved = false;
    m_receivedHeader->clear();
    m_receivedLength->clear();
    m_receivedBlocks->clear();
}

void TransferPanel::appendLog(const QString &line)
{
    // The link check every 5 s shows in the window's connection indicator, not here.
    if (m_session && m_session->lastResult().operation == Operation::Ping)
        return;
    m_log->appendPlainText(QTime::currentTime().toString(QStringLiteral("HH:mm:ss.zzz  ")) + line);
}

bool TransferPanel::receive()
{
    if (!m_session || m_session->isBusy())
        return false;
    m_hint->setVisible(false);
    m_banner->setVisible(false);
    clearReceived();
    m_startUs = m_clock.nowUs();
    m_progress->setValue(0);
    m_status->setText(tr("Receiving from the controller…"));
    m_session->setTiming(SessionTiming{});
    m_session->save();
    updateEnabled();
    return true;
}

bool TransferPanel::send()
{
    if (!m_session || m_session->isBusy() || m_toSend.isEmpty())
        return false;
    m_hint->setVisible(false);
    m_banner->setVisible(false);
    const ControllerHeader header = ControllerHeader::fromText(m_header->text());
    if (!header.ok()) {
        m_status->setText(tr("Transfer failed."));
        showFailure(header.error);
        return false;
    }
    if (m_toSendFamily && *m_toSendFamily != m_session->family()) {
        m_status->setText(tr("Transfer failed."));
        showFailure(tr("%1 holds %2 data (saved from a %2 control): is the wrong system "
                       "selected? Choose %2 and connect again. Nothing was sent.")
                        .arg(QFileInfo(m_toSendPath).fileName(), familyName(*m_toSendFamily)));
        return false;
    }
    m_startUs = m_clock.nowUs();
    m_progress->setValue(0);
    m_status->setText(tr("Sending %1 to the controller…").arg(QFileInfo(m_toSendPath).fileName()));
    m_session->setTiming(SessionTiming{});
    m_session->load(header.header(), m_toSend, m_sendAnyway->isChecked());
    updateEnabled();
    return true;
}

void TransferPanel::onProgress(qint64 done, qint64 total)
{
    if (total <= 0)
        return;
    m_progress->setMaximum(int(total));
    m_progress->setValue(int(done));
    const double left = estimateSecondsLeft(done, total, m_clock.nowUs() - m_startUs, m_baud);
    m_progressText->setText(
        tr("%1 of %2 bytes, %3 left").arg(done).arg(total).arg(formatSeconds(left)));
}

void TransferPanel::onFinished(const TransferResult &result)
{
    if (result.operation == Operation::Ping)
        return; // the window shows link checks
    if (result.ok()) {
        const qint64 elapsedS = result.elapsedUs / 1000000;
        m_progressText->setText(
            tr("%1 bytes in %2").arg(result.data.size()).arg(formatSeconds(double(elapsedS))));
    }
    if (result.operation == Operation::Save && result.ok()) {
        m_received = result;
        m_receivedFamily = m_session ? m_session->family() : Family::K51;
        m_receivedHeader->setText(QString::fromLatin1(headerText(result.header)));
        m_receivedLength->setText(tr("%1 bytes (0x%2)")
                                      .arg(result.data.size())
                                      .arg(QString::number(result.data.size(), 16).toUpper()));
        m_receivedBlocks->setText(TransferSession::describeImage(result.image));
        m_status->setText(tr("Received. Press Save to store the data in a file."));
    } else if (result.operation == Operation::Load && result.ok()) {
        m_status->setText(tr("Sent; the controller confirmed the transfer."));
        if (m_session && m_session->family() != Family::HardChrome &&
            m_session->family() != Family::Table) {
            m_hint->setText(tr("On the controller, TCHIN programs show \"no prg set\" once after "
                               "a transfer: set up the X axis first — select the TCHIN program "
                               "in AUT and hold RES."));
            m_hint->setVisible(true);
        }
    } else if (result.error == TransferError::Cancelled) {
        m_status->setText(tr("Cancelled."));
        showFailure(tr("Cancelled: %1").arg(result.message));
        m_progressText->clear();
    } else {
        const QString what = result.operation == Operation::Save
                                 ? tr("Receiving from the controller failed")
                                 : tr("Sending to the controller failed");
        m_status->setText(tr("Transfer failed."));
        showFailure(tr("%1: %2").arg(what, result.message));
        m_progressText->clear();
    }
    updateEnabled();
    emit transferFinished(result);
}

QString TransferPanel::chooseFile(FileChoice choice, const QString &suggestion)
{
    if (m_chooser)
        return m_chooser(choice, suggestion);
    if (choice == FileChoice::SaveReceived)
        return QFileDialog::getSaveFileName(
            this, tr("Save the controller's data"), suggestion,
            tr("Frezka grinder file, keeps the header (*.frg);;Bare data for the old tools "
               "(*.bin)"));
    return QFileDialog::getOpenFileName(this, tr("Choose the file to send"), suggestion);
}

void TransferPanel::chooseSaveFile()
{
    const QString suggestion = QString::fromLatin1(headerText(m_received.header)).trimmed();
    const QString path = chooseFile(FileChoice::SaveReceived,
                                    suggestion.isEmpty() ? QStringLiteral("programs.frg")
                                                         : suggestion + QStringLiteral(".frg"));
    if (!path.isEmpty())
        saveReceived(path);
}

void TransferPanel::chooseSendFile()
{
    const QString path = chooseFile(FileChoice::OpenToSend, m_toSendPath);
    if (!path.isEmpty())
        openFileToSend(path);
}

bool TransferPanel::saveReceived(const QString &path)
{
    if (m_received.data.isEmpty())
        return false;
    // A Frezka grinder file keeps the header and the system; ".bin" is the old tools' bare data.
    QByteArray bytes = m_received.data;
    if (!path.endsWith(QLatin1String(".bin"), Qt::CaseInsensitive)) {
        GrinderFile grinderFile;
        grinderFile.family = m_receivedFamily;
        grinderFile.header = m_received.header;
        grinderFile.data = Bytes(m_received.data.begin(), m_received.data.end());
        const Bytes encoded = encodeGrinderFile(grinderFile);
        bytes =
            QByteArray(reinterpret_cast<const char *>(encoded.data()), qsizetype(encoded.size()));
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        m_status->setText(tr("Cannot write %1: %2. The received data are kept; choose another "
                             "file.")
                              .arg(path, file.errorString()));
        return false;
    }
    m_receivedSaved = true;
    m_status->setText(tr("Saved %1 bytes to %2.").arg(m_received.data.size()).arg(path));
    appendLog(m_status->text());
    return true;
}

bool TransferPanel::openFileToSend(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        m_status->setText(tr("Cannot read %1: %2").arg(path, file.errorString()));
        return false;
    }
    const QByteArray bytes = file.readAll();
    std::string why;
    const auto decoded = decodeGrinderFile(Bytes(bytes.begin(), bytes.end()), why);
    if (!decoded) {
        m_status->setText(tr("%1 is damaged: %2").arg(path, QString::fromStdString(why)));
        return false;
    }
    m_toSend = QByteArray(reinterpret_cast<const char *>(decoded->data.data()),
                          qsizetype(decoded->data.size()));
    m_toSendFamily = decoded->container ? std::optional<Family>(decoded->family) : std::nullopt;
    m_toSendPath = path;
    m_sendFile->setText(path);
    const ImageReport report = checkImage(Bytes(m_toSend.begin(), m_toSend.end()));
    m_sendInfo->setText(tr("%1 bytes; inner blocks: %2")
                            .arg(m_toSend.size())
                            .arg(TransferSession::describeImage(report)));
    // The header saved with the data; else, as K51LOAD 2.20, the file name.
    m_header->setText(decoded->container
                          ? QString::fromLatin1(headerText(decoded->header))
                          : QFileInfo(path).completeBaseName().left(int(kHeaderSize)));
    updateEnabled();
    return true;
}

bool TransferPanel::sendData(const QByteArray &data, const QString &label, const QString &header,
                             Family family)
{
    m_toSend = data;
    m_toSendPath = label;
    m_toSendFamily = family;
    m_sendFile->setText(label);
    m_sendInfo->setText(tr("%1 bytes from the editor").arg(data.size()));
    m_header->setText(header);
    updateEnabled();
    return send();
}

void TransferPanel::updateHeaderNote()
{
    const QString typed = m_header->text();
    const ControllerHeader header = ControllerHeader::fromText(typed);
    const QString note = header.ok() ? ControllerHeader::mappingNote(typed, header) : header.error;
    m_headerNote->setText(note);
    m_headerNote->setVisible(!note.isEmpty());
}

QString TransferPanel::headerNote() const
{
    return m_headerNote->isHidden() ? QString() : m_headerNote->text();
}

void TransferPanel::setHeaderText(const QString &text)
{
    m_header->setText(text.left(int(kHeaderSize)));
}

} // namespace frezka::gui
