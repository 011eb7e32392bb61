#include "gui/grinder/grinderwindow.h"

#include "driver/grinder/emulatortransport.h"
#include "gui/grinder/hardchromeeditor.h"
#include "gui/grinder/portsettings.h"
#include "gui/grinder/serialmonitor.h"
#include "gui/grinder/zpositionpanel.h"

#include <QCloseEvent>
#include <QComboBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace frezka::gui {

using namespace frezka::grinder;

GrinderWindow::GrinderWindow(QWidget *parent)
    : QWidget(parent)
    , m_resumeTimer(new QTimer(this))
    , m_port(new PortSettingsRow(true, this))
    , m_family(new QComboBox(this))
    , m_mode(new QComboBox(this))
    , m_connectButton(new QPushButton(tr("Connect"), this))
    , m_connection(new QLabel(this))
    , m_linkTimer(new QTimer(this))
    , m_tabs(new QTabWidget(this))
    , m_transferPanel(new TransferPanel(m_clock, this))
    , m_zPanel(new ZPositionPanel(this))
    , m_monitor(new SerialMonitor(this))
    , m_hardChrome(new HardChromeEditor(this))
{
    setWindowFlag(Qt::Window); // a window of its own even when given a parent
    setWindowTitle(tr("Grinder transfer"));
    m_family->setObjectName(QStringLiteral("family"));
    m_mode->setObjectName(QStringLiteral("linkMode"));
    m_connectButton->setObjectName(QStringLiteral("connectButton"));
    m_connection->setObjectName(QStringLiteral("connectionState"));
    m_family->addItem(tr("K51 programs (K51LOAD/K51SAVE, KCOMM)"), int(Family::K51));
    m_family->addItem(tr("ANC programs (ANCLOAD/ANCSAVE)"), int(Family::Anc));
    m_family->addItem(tr("ANC hard-chrome data (HEDIT)"), int(Family::HardChrome));
    m_family->addItem(tr("K51 table (APROXTAB), PC → controller only"), int(Family::Table));
    m_mode->addItem(tr("Program transfer"), int(LinkMode::Programs));
    m_mode->addItem(tr("Z position, FORM=1 (ASCII)"), int(LinkMode::ZForm1));
    m_mode->addItem(tr("Z position, FORM=2 (binary)"), int(LinkMode::ZForm2));

    auto *connectionBox = new QGroupBox(tr("Connection"), this);
    auto *row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Control:"), this));
    row->addWidget(m_family, 1);
    row->addWidget(new QLabel(tr("Mode:"), this));
    row->addWidget(m_mode, 1);
    row->addWidget(m_connectButton);
    auto *boxLayout = new QVBoxLayout(connectionBox);
    boxLayout->addWidget(m_port);
    boxLayout->addLayout(row);
    boxLayout->addWidget(m_connection);

    m_tabs->addTab(m_transferPanel, tr("Program transfer"));
    m_tabs->addTab(m_zPanel, tr("Z position"));
    m_tabs->addTab(m_monitor, tr("Serial monitor"));
    m_tabs->addTab(m_hardChrome, tr("HEDIT data"));
    connect(m_hardChrome, &HardChromeEditor::receivedDataWanted, this, [this] {
        m_hardChrome->setData(m_transferPanel->receivedData(), m_transferPanel->receivedHeader());
    });
    connect(m_hardChrome, &HardChromeEditor::sendRequested, this,
            [this](const QByteArray &data, const QString &header) {
                m_tabs->setCurrentWidget(m_transferPanel);
                m_transferPanel->sendData(data, tr("HEDIT editor"), header, Family::HardChrome);
            });
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(connectionBox);
    layout->addWidget(m_tabs, 1);

    m_connection->setWordWrap(true); // a long message must not widen the window for good
    m_resumeTimer->setSingleShot(true);
    connect(m_resumeTimer, &QTimer::timeout, this, [this] {
        if (!m_session)
            return;
        m_linkTimer->start();
        checkLink();
    });
    m_linkTimer->setInterval(kLinkCheckIntervalMs);
    connect(m_linkTimer, &QTimer::timeout, this, &GrinderWindow::checkLink);
    connect(m_connectButton, &QPushButton::clicked, this, &GrinderWindow::onConnectClicked);
    // Choosing a control sets its usual rate (ANCLOAD/ANCSAVE 4800 Bd, K51 and HEDIT 9600);
    // the rate can still be changed after.
    connect(m_family, &QComboBox::activated, this, [this] {
        grinder::SerialSettings s = m_port->settings();
        s.baud = familyInfo(static_cast<Family>(m_family->currentData().toInt())).defaultBaud;
        m_port->setSettings(s);
    });
    loadSettings();
    setLinkUp(false, QString());
    m_connection->setText(tr("Not connected."));
    resize(900, 650);
}

GrinderWindow::~GrinderWindow()
{
    saveSettings();
    disconnectPort();
}

void GrinderWindow::loadSettings()
{
    // KCOMMcfg.txt's job: port and line settings survive a restart.
    QSettings settings;
    settings.beginGroup(QStringLiteral("grinder"));
    SerialSettings s;
    s.portName =
        settings.value(QStringLiteral("port"), PortSettingsRow::emulatorPortName()).toString();
    s.baud = settings.value(QStringLiteral("baud"), 9600).toInt();
    s.dataBits = settings.value(QStringLiteral("dataBits"), 8).toInt();
    s.parity =
        settings.value(QStringLiteral("parity"), QStringLiteral("n")).toString().at(0).toLatin1();
    s.stopBits = settings.value(QStringLiteral("stopBits"), 1).toInt();
    m_port->setSettings(s);
    // K51 on first start, as the documentation says.
    const int family =
        m_family->findData(settings.value(QStringLiteral("family"), int(Family::K51)).toInt());
    m_family->setCurrentIndex(family < 0 ? 0 : family);
}

void GrinderWindow::saveSettings() const
{
    QSettings settings;
    settings.beginGroup(QStringLiteral("grinder"));
    const SerialSettings s = m_port->settings();
    settings.setValue(QStringLiteral("port"), s.portName);
    settings.setValue(QStringLiteral("baud"), s.baud);
    settings.setValue(QStringLiteral("dataBits"), s.dataBits);
    settings.setValue(QStringLiteral("parity"), QString(QChar(s.parity)));
    settings.setValue(QStringLiteral("stopBits"), s.stopBits);
    settings.setValue(QStringLiteral("family"), m_family->currentData().toInt());
}

void GrinderWindow::setSerialSettings(const SerialSettings &settings)
{
    m_port->setSettings(settings);
}

void GrinderWindow::setFamily(Family family)
{
    m_family->setCurrentIndex(m_family->findData(int(family)));
}

void GrinderWindow::setLinkMode(LinkMode mode)
{
    m_mode->setCurrentIndex(m_mode->findData(int(mode)));
}

void GrinderWindow::onConnectClicked()
{
    if (isConnected())
        disconnectPort();
    else
        connectPort();
}

bool GrinderWindow::connectPort()
{
    disconnectPort();
    const SerialSettings settings = m_port->settings();
    const auto family = static_cast<Family>(m_family->currentData().toInt());
    const auto mode = static_cast<LinkMode>(m_mode->currentData().toInt());
    if (settings.portName == PortSettingsRow::emulatorPortName()) {
        EmulatorConfig config;
        // A table goes to a K51 set to table transfer (KONFIG6 = 3).
        config.family = family == Family::Table ? Family::K51 : family;
        config.mode = mode != LinkMode::Programs ? TransferMode::ZPosition
                      : family == Family::Table  ? TransferMode::Table
                                                 : TransferMode::Programs;
        config.zForm = mode == LinkMode::ZForm2 ? 2 : 1;
        m_transport = std::make_unique<EmulatorTransport>(m_clock, config, settings.baud, 10000);
    } else {
        m_transport = std::make_unique<SerialTransport>(settings);
    }
    QString error;
    if (!m_transport->open(&error)) {
        m_transport.reset();
        m_connection->setText(tr("Cannot connect: %1").arg(error));
        return false;
    }
    connect(m_transport.get(), &Transport::failed, this,
            [this](const QString &message) { setLinkUp(false, message); });
    m_port->setEnabled(false);
    m_family->setEnabled(false);
    m_mode->setEnabled(false);
    m_connectButton->setText(tr("Disconnect"));
    if (mode == LinkMode::Programs) {
        m_session = std::make_unique<TransferSession>(*m_transport, m_clock, family);
        connect(m_session.get(), &TransferSession::finished, this,
                &GrinderWindow::onTransferFinished);
        m_transferPanel->setSession(m_session.get(), settings.baud);
        m_tabs->setCurrentWidget(m_transferPanel);
        m_linkTimer->start();
        checkLink();
    } else {
        m_zSession =
            std::make_unique<ZLinkSession>(*m_transport, m_clock, mode == LinkMode::ZForm2 ? 2 : 1);
        m_zPanel->setSession(m_zSession.get());
        m_tabs->setCurrentWidget(m_zPanel);
        m_connection->setText(tr("Open: %1 at %2 Bd.").arg(m_transport->name()).arg(settings.baud));
    }
    return true;
}

void GrinderWindow::disconnectPort()
{
    // A transfer in progress ends visibly, not silently with the session.
    if (m_session && m_session->isBusy()) {
        m_disconnecting = true;
        m_session->cancel(tr("Disconnected during the transfer."));
        m_disconnecting = false;
    }
    m_linkTimer->stop();
    m_resumeTimer->stop();
    m_transferPanel->setSession(nullptr);
    m_zPanel->setSession(nullptr);
    m_session.reset();
    m_zSession.reset();
    if (m_transport)
        m_transport->close();
    m_transport.reset();
    m_port->setEnabled(true);
    m_family->setEnabled(true);
    m_mode->setEnabled(true);
    m_connectButton->setText(tr("Connect"));
    setLinkUp(false, QString());
    m_connection->setText(tr("Not connected."));
}

void GrinderWindow::checkLink()
{
    if (!m_session || m_session->isBusy())
        return; // a transfer in progress shows the link by itself
    SessionTiming timing;
    timing.maxRetries = 0;
    timing.replyTimeoutMs = 2000;
    timing.pauseMs = 0;
    m_session->setTiming(timing);
    m_session->ping();
    m_transferPanel->updateEnabled();
}

void GrinderWindow::onTransferFinished(const TransferResult &result)
{
    if (result.operation == Operation::Ping || result.ok()) {
        setLinkUp(result.ok(), result.ok() ? QString() : result.message);
    } else if (m_disconnecting || !m_session) {
        // the window is closing the port: no link check
    } else if (result.error == TransferError::Cancelled && result.controllerBusyUs > 0) {
        // The controller finishes (or drops) its message first: a check now would fail.
        m_linkTimer->stop();
        m_resumeTimer->start(int(result.controllerBusyUs / 1000) + 200);
        m_connection->setText(tr("Waiting for the controller to finish its message (about %1 "
                                 "s)…")
                                  .arg(qMax(1, qRound(result.controllerBusyUs / 1e6))));
    } else {
        // After a failed transfer, find out at once whether the link is there (once every
        // slot has seen this result).
        QTimer::singleShot(0, this, &GrinderWindow::checkLink);
    }
    m_transferPanel->updateEnabled();
}

void GrinderWindow::setLinkUp(bool up, const QString &detail)
{
    m_linkUp = up;
    m_transferPanel->setLinkUp(up);
    if (!m_transport)
        return;
    const QString state = up ? tr("Connected") : tr("No connection");
    m_connection->setText(detail.isEmpty()
                              ? tr("%1 — %2").arg(state, m_transport->name())
                              : tr("%1 — %2: %3").arg(state, m_transport->name(), detail));
    m_connection->setStyleSheet(
        up ? QStringLiteral("QLabel { color: #1a7f1a; font-weight: bold; }")
           : QStringLiteral("QLabel { color: #b00020; font-weight: bold; }"));
}

void GrinderWindow::closeEvent(QCloseEvent *event)
{
    if (m_transferPanel->hasUnsavedData()) {
        const bool close =
            m_closeConfirmer
                ? m_closeConfirmer()
                : QMessageBox::question(this, tr("Grinder transfer"),
                                        tr("The data received from the controller have not been "
                                           "saved. Close and discard them?"),
                                        QMessageBox::Discard | QMessageBox::Cancel,
                                        QMessageBox::Cancel) == QMessageBox::Discard;
        if (!close) {
            event->ignore();
            return;
        }
    }
    disconnectPort();
    event->accept();
}

QString GrinderWindow::connectionText() const
{
    return m_connection->text();
}

} // namespace frezka::gui
