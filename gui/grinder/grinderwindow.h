#pragma once
// "Grinder transfer" window (issue 7): moves programs between the PC and ANC/K51 grinding
// controls like the vendor's KCOMM, plus the Z-position link and a serial monitor.
//
// Connection: port and line settings, the family (K51 / ANC / HEDIT) and the link mode
// (program transfer, Z-position FORM=1 or FORM=2). In program mode the window sends ENQ every
// 5 s and shows "Connected" / "No connection"; the transfer buttons work only while connected.
// The port list offers "emulator": an in-process controller in real time, for trying it out.

#include "driver/grinder/clock.h"
#include "driver/grinder/family.h"
#include "driver/grinder/transfersession.h"
#include "driver/grinder/zlinksession.h"
#include "gui/grinder/transferpanel.h"

#include <QWidget>

#include <functional>
#include <memory>

class QComboBox;
class QLabel;
class QPushButton;
class QTabWidget;
class QTimer;

namespace frezka::gui {

class HardChromeEditor;
class PortSettingsRow;
class SerialMonitor;
class ZPositionPanel;

class GrinderWindow : public QWidget
{
    Q_OBJECT
public:
    enum class LinkMode { Programs, ZForm1, ZForm2 };
    static constexpr int kLinkCheckIntervalMs = 5000;

    explicit GrinderWindow(QWidget *parent = nullptr);
    ~GrinderWindow() override;

    // Programmatic control (menus, scripts, tests): no dialogs involved.
    void setSerialSettings(const grinder::SerialSettings &settings);
    void setFamily(grinder::Family family);
    void setLinkMode(LinkMode mode);
    bool connectPort();
    void disconnectPort();
    bool isConnected() const { return m_transport != nullptr; }
    bool isLinkUp() const { return m_linkUp; }
    QString connectionText() const;
    void checkLink(); // one ENQ now

    // Asked before the window closes with received data not saved; true closes. The default
    // asks with a message box; tests set their own so no modal dialog appears.
    using CloseConfirmer = std::function<bool()>;
    void setCloseConfirmer(CloseConfirmer confirmer) { m_closeConfirmer = std::move(confirmer); }

    TransferPanel *transferPanel() const { return m_transferPanel; }
    ZPositionPanel *zPositionPanel() const { return m_zPanel; }
    SerialMonitor *serialMonitor() const { return m_monitor; }
    HardChromeEditor *hardChromeEditor() const { return m_hardChrome; }
    grinder::Transport *transport() const { return m_transport.get(); }

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void onConnectClicked();
    void onTransferFinished(const grinder::TransferResult &result);
    void setLinkUp(bool up, const QString &detail);
    void loadSettings();
    void saveSettings() const;

    grinder::RealClock m_clock;
    std::unique_ptr<grinder::Transport> m_transport;
    std::unique_ptr<grinder::TransferSession> m_session;
    std::unique_ptr<grinder::ZLinkSession> m_zSession;
    bool m_linkUp = false;
    bool m_disconnecting = false;
    CloseConfirmer m_closeConfirmer;
    QTimer *m_resumeTimer; // restarts the link check once a cancelled controller is done

    PortSettingsRow *m_port;
    QComboBox *m_family;
    QComboBox *m_mode;
    QPushButton *m_connectButton;
    QLabel *m_connection;
    QTimer *m_linkTimer;
    QTabWidget *m_tabs;
    TransferPanel *m_transferPanel;
    ZPositionPanel *m_zPanel;
    SerialMonitor *m_monitor;
    HardChromeEditor *m_hardChrome;
};

} // namespace frezka::gui
