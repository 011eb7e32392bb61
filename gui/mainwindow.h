#pragma once
// MainWindow: the one operating screen — toolpath view in the middle, DRO, run controls, jog and
// outputs on the left, the program listing on the right, console and speed plot below, the
// unit's LEDs in the status bar. It renders what the controller reports and asks the
// controller to act; it keeps no machine state of its own.

#include "machine/machineconfig.h"

#include <QMainWindow>
#include <QPointer>

#include <memory>

class QLabel;
class QMenu;
class QProgressBar;
class QDockWidget;

namespace frezka::gui {

class ConsoleWidget;
class DroWidget;
class IoPanel;
class JogPanel;
class OutputsPanel;
class ProgramListing;
class ProgramSession;
class RunPanel;
class SpeedPlot;
class ToolpathView;
class MachineSession;
class SettingsDialog;

struct MainWindowOptions
{
    enum class View { Auto, Software, OpenGl } view = View::Auto;
    bool restoreLayout = true; // from QSettings
};

class MainWindow : public QMainWindow
{
    Q_OBJECT

public:
    explicit MainWindow(const MainWindowOptions &options = {}, QWidget *parent = nullptr);
    ~MainWindow() override;

    // Starts loading a program in the background; loadFinished() tells the outcome.
    void openProgram(const QString &path);

    ToolpathView *toolpathView() const { return m_view; }
    DroWidget *dro() const { return m_dro; }
    RunPanel *runPanel() const { return m_run; }
    JogPanel *jogPanel() const { return m_jog; }
    OutputsPanel *outputsPanel() const { return m_outputs; }
    ConsoleWidget *console() const { return m_console; }
    ProgramListing *listing() const { return m_listing; }
    SpeedPlot *speedPlot() const { return m_plot; }
    IoPanel *ioPanel() const { return m_io; }
    ProgramSession *program() const { return m_program; }
    MachineSession *machine() const { return m_machine; }
    const machine::MachineConfig &profile() const { return m_profile; }
    QString profilePath() const { return m_profilePath; }
    // Makes a (valid) profile the active one: axes, limits, outputs, connection.
    void applyProfile(const machine::MachineConfig &config, const QString &path);
    // Opens the settings dialog (non-modal) and returns it.
    class SettingsDialog *openSettings();
    // The last message shown to the user as an error (tests read it; no modal dialog needed).
    QString lastError() const { return m_lastError; }

signals:
    void errorShown(const QString &message);

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void keyReleaseEvent(QKeyEvent *event) override;

private:
    void buildDocks();
    void buildMenus();
    void retranslate();
    void connectProgram();
    void connectMachine();
    void showError(const QString &message);
    void updateRecentMenu();
    void addRecent(const QString &path);
    void openDialog();
    void checkProgramLimits();
    void updateRunPhase();
    bool jogKey(QKeyEvent *event, bool pressed);

    ToolpathView *m_view;
    DroWidget *m_dro;
    RunPanel *m_run;
    JogPanel *m_jog;
    OutputsPanel *m_outputs;
    ConsoleWidget *m_console;
    ProgramListing *m_listing;
    SpeedPlot *m_plot;
    IoPanel *m_io;
    QLabel *m_connection, *m_unit, *m_state, *m_file;
    QProgressBar *m_loadProgress;
    QDockWidget *m_droDock, *m_runDock, *m_jogDock, *m_outputsDock, *m_programDock, *m_consoleDock,
        *m_plotDock;
    QMenu *m_fileMenu, *m_recentMenu, *m_machineMenu, *m_viewMenu, *m_toolsMenu, *m_helpMenu;
    QAction *m_openAction, *m_quitAction, *m_connectAction, *m_disconnectAction, *m_settingsAction,
        *m_unitConfigAction, *m_aboutAction, *m_grinderAction = nullptr, *m_resetLayoutAction;
    ProgramSession *m_program;
    MachineSession *m_machine;
    QString m_lastError;
    machine::MachineConfig m_profile;
    QString m_profilePath;
    QPointer<SettingsDialog> m_settings;
    QByteArray m_defaultState;
};

} // namespace frezka::gui
