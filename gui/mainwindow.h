#pragma once
// MainWindow: the one operating screen — toolpath view in the middle, DRO, run controls, jog and
// outputs on the left, the program listing on the right, console and speed plot below, the
// unit's LEDs in the status bar. It renders what the controller reports and wires the operator's
// controls to the session layer (run workflow, console, work offsets), which keeps every piece
// of workflow state; the window keeps none of its own.

#include "actualspeed.h"

#include "driver/link/machinestate.h"
#include "gcode/heightmap.h"
#include "machine/machineconfig.h"
#include "programview.h"

#include "session/consolesession.h"
#include "session/programmodes.h"
#include "session/remainingtime.h"
#include "session/runworkflow.h"
#include "session/virtualclocklink.h"
#include "session/workoffsets.h"

#include <QDateTime>
#include <QMainWindow>
#include <QPointer>

#include <memory>
#include <optional>
#include <utility>
#include <vector>

class QLabel;
class QMenu;
class QProgressBar;
class QDockWidget;
class QFileSystemWatcher;

namespace frezka::driver {
class MachineController;
struct MachineError;
} // namespace frezka::driver

namespace frezka::gui {

class ConsoleWidget;
class DroWidget;
class IoPanel;
class ToolTableDialog;
class HeightMapDialog;
class JogPanel;
class LoadProgress;
class OutputsPanel;
class PlacementBar;
class ProgramInfoDialog;
class ProgramListing;
class RunPanel;
class SpeedPlot;
class StatusPanel;
enum class OperatorAction;
class ToolpathView;
class HoldBanner;
class SettingsDialog;
class UnitConfigDialog;
class UnitsPanel;

struct MainWindowOptions
{
    enum class View { Auto, Software, OpenGl } view = View::Auto;
    bool restoreLayout = true; // from QSettings
    // Virtual: the built-in emulator on a virtual clock turned from the event loop, as fast as
    // the computer allows while the machine moves (frezka --clock virtual; docs/gui.md). A port
    // is refused then. Real (the default): the emulator or the port in real time.
    enum class Clock { Real, Virtual } clock = Clock::Real;
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
    // Machine › Save serial trace… without its file dialog: the session's serial trace
    // (driver/link/tracerecorder.h) to `path`; false with the reason, translated.
    bool saveSerialTrace(const QString &path, QString *error) const;
    ProgramListing *listing() const { return m_listing; }
    SpeedPlot *speedPlot() const { return m_plot; }
    IoPanel *ioPanel() const { return m_io; }
    StatusPanel *statusPanel() const { return m_status; }
    // Every unit on the machine's line (View › Units on the line). mainwindow_units.cpp.
    UnitsPanel *unitsPanel() const { return m_units; }
    ProgramSession *program() const { return m_program; }
    driver::MachineController *controller() const { return m_controller; }
    // The link the workflow runs on (the controller's, or the virtual clock's) and its state.
    session::MachineLink *link() const { return m_link; }
    const driver::MachineState &machineState() const { return m_link->state(); }
    // The built-in emulator on the virtual clock (MainWindowOptions::Clock::Virtual), else null.
    session::VirtualClockLink *virtualClock() const { return m_virtualClock; }
    HoldBanner *holdBanner() const { return m_hold; }
    PlacementBar *placementBar() const { return m_placement; }
    session::WorkOffsets *offsets() const { return m_offsets; }
    session::RunWorkflow *workflow() const { return m_workflow; }
    session::ConsoleSession *consoleSession() const { return m_consoleSession; }
    const session::OffsetTable &workOffsets() const { return m_offsets->systems(); }
    int activeOffset() const { return m_offsets->active(); }

    // Operator actions (the buttons call these; tests too).
    // Run was asked before homing: offer "Home and run" (session::RunWorkflow::homingNeeded).
    void askToHome();
    void connectToUnit();
    void disconnectFromUnit();
    // Runs the loaded program; re-plans first when the machine is not where the plan starts.
    void runProgram();
    // Re-interprets and re-plans the program and reports the outcome in words.
    void checkProgram();
    // Run from a line (session/runfromline.h): the program is loaded again as the job from that
    // line (the preview shows the approach); Run runs it. runWholeProgram() goes back (also
    // after the job has ended). The listing's "Run from this line…" and Machine › Run from
    // line… call it.
    void runFromLine(int line);
    void runWholeProgram();
    // Reads the loaded program's file again (File › Reload), as a fresh open: checked, planned.
    // Refused while its job runs.
    void reloadProgram();
    // File › Program info: size, extent, tools and their times (non-modal), shown and returned.
    ProgramInfoDialog *openProgramInfo();
    // Sets the work zero of an axis (-1 = all) at the current machine position.
    void setWorkZero(int axis);
    void selectWorkOffset(int index);
    // A manual line: "!..." is a raw unit command, anything else one block of G-code in the
    // console's modes (session::ConsoleSession).
    void executeManualLine(const QString &line);
    void jogStep(int axis, double deltaMm, double feedMmPerMin);
    const machine::MachineConfig &profile() const { return m_workflow->profile(); }
    QString profilePath() const { return m_profilePath; }
    // Makes a (valid) profile the active one: axes, limits, outputs, connection.
    void applyProfile(const machine::MachineConfig &config, const QString &path);
    // Opens the settings dialog (non-modal) and returns it.
    class SettingsDialog *openSettings();
    // Opens the unit configuration (EEPROM) page (non-modal) and returns it.
    class UnitConfigDialog *openUnitConfig();
    // Machine › Tool table: opens the profile's tool table (non-modal) and returns it; null (with
    // the error shown) when the profile names no table file. mainwindow_tools.cpp.
    class ToolTableDialog *openToolTable();
    // Machine › Height map…: probe, show, save / load, apply to the program (non-modal), shown
    // and returned; it probes on `link` (tests: a simulated one), null: the window's own.
    // mainwindow_heightmap.cpp.
    HeightMapDialog *openHeightMap(session::MachineLink *link = nullptr);
    // The height map file (docs/height-map.md) applied to the program, as the dialog's Apply
    // without moving the work zero (frezka --height-map); false with *error set when unreadable.
    bool applyHeightMapFile(const QString &path, QString *error);
    // Machine › Probe work zero… (issue 19 item 2): Z from a plate, X/Y from an edge or corner.
    class ProbeZeroDialog *openProbeZero();
    // The last message shown to the user as an error (tests read it; no modal dialog needed).
    QString lastError() const { return m_lastError; }

signals:
    void errorShown(const QString &message);
    // A Check (re-interpretation and planning) has finished; ok = the program can run.
    void programChecked(bool ok);

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
    // The status bar's Cancel of a load: the program loaded before stays, and the window says so.
    void connectLoadCancel();
    // "part.nc — 1 200 lines · G21: ..." for the status bar: the loaded program.
    QString programFileText() const;
    void connectMachine();
    void buildUnitsDock();
    // The units of the profile's line.units (their profiles read beside it) to the driver and
    // the Units panel before a connect; false, with the error shown, when one cannot be read.
    bool prepareLine(const machine::MachineConfig &config);
    void onMachineUnitChanged(int unit);
    void connectControls();
    void connectOutputs();
    void showError(const QString &message);
    void updateRecentMenu();
    void addRecent(const QString &path);
    void openDialog();
    void checkProgramLimits();
    // The loaded file changed on disk: ask whether to reload it (after the job, if one runs).
    void onProgramFileChanged(const QString &path);
    void promptReload();
    // Where the loaded program sits against the travel (the placement bar) / its new work zero.
    void updatePlacement();
    void updateProgramInfo();
    // mm or inch (Settings › Application) into the DRO, the jog, the status panel, the plot.
    void applyDisplayUnits();
    // "G21: the program is in mm" — the loaded program's units as its first lines set them.
    QString programUnitsText() const;
    void placeWorkOffset(const session::Axes4 &offsetMm);
    void buildCentral();
    void onState(const driver::MachineState &state);
    void onMachineError(const driver::MachineError &error);
    void onLogLine(const QString &line);
    void updateHold(const driver::MachineState &state);
    QString holdDetail(const driver::MachineState &state) const;
    void showJob(const driver::MachineState &state);
    void updateProgress(const driver::MachineState &state);
    void updateStatus(const driver::MachineState &state);
    session::ProgramModes programModesAt(std::uint32_t line);
    QString connectionText(const driver::MachineState &state) const;
    std::uint32_t shownLine(const driver::MachineState &state) const;
    QString logLineText(const QString &line) const;
    void onOffsetsChanged();
    void offerProgram();
    // A program that probes for itself (mainwindow_probefollow.cpp): the run workflow follows
    // its probes (session/probefollow.h); the preview shows the part after the next probe not
    // run yet as provisional, and the program as re-interpreted after each probe.
    void connectProbeFollow();
    void offerProbeFollow();
    void onProbeFollowShown();
    void showProvisional();
    void onJobStarted();
    void onJobFinished(bool ok);
    void onChecked(bool ok);
    void onConnected();
    QString eepromDifferenceText(const driver::EepromDifference &difference) const;
    void updateRunPhase();
    bool jogKey(QKeyEvent *event, bool pressed);
    void installShortcuts();
    void buildFromLineActions(); // Machine › Run from line…, Run the whole program
    void buildToolTableAction(); // Machine › Tool table…
    void buildHeightMapAction(); // Machine › Height map…
    // View › Height map and its Z scale (the map's mesh in the toolpath view), from the settings.
    void buildHeightMapViewActions();
    void retranslateHeightMapView();
    // The view shows the dialog's map (probed so far, or loaded), else the program's, else none.
    void showHeightMapInView();
    // The program loaded again bent to the map (nullopt: as written); the work's Z zero on the
    // map's first point when zeroAtReference.
    void applyHeightMap(const std::optional<gcode::HeightMap> &map, bool zeroAtReference);
    void buildTraceAction();   // Machine › Save serial trace… (mainwindow_trace.cpp)
    void loadToolTable();      // the profile's table into the program session
    void writeBackToolTable(); // after a run: the table as the program's G10 L1.. left it
    void keepWorkOffsets();    // after a run: G54..G59.3 as the program's G10 L2/L20 left them
    // Machine › Commission this machine… (mainwindow_commission.cpp)
    void buildCommissionAction();
    // At an M6 hold: the tool's comment, length and diameter from the table (empty: none).
    QString toolChangeText(const driver::MachineState &state) const;
    void askRunFromLine();
    void onFromLineLoaded();
    // The keys changed in the settings: the QShortcuts take them.
    void applyShortcutKeys();
    void operatorKey(OperatorAction action);

    ToolpathView *m_view;
    DroWidget *m_dro;
    RunPanel *m_run;
    JogPanel *m_jog;
    OutputsPanel *m_outputs;
    ConsoleWidget *m_console;
    ProgramListing *m_listing;
    SpeedPlot *m_plot;
    IoPanel *m_io;
    StatusPanel *m_status;
    UnitsPanel *m_units = nullptr;
    QDockWidget *m_unitsDock = nullptr;
    QLabel *m_connection, *m_unit, *m_state, *m_file;
    LoadProgress *m_loadProgress;
    QDockWidget *m_statusDock, *m_droDock, *m_runDock, *m_jogDock, *m_outputsDock, *m_programDock,
        *m_consoleDock, *m_plotDock;
    QMenu *m_fileMenu, *m_recentMenu, *m_machineMenu, *m_viewMenu, *m_toolsMenu, *m_helpMenu;
    QAction *m_openAction, *m_reloadAction, *m_infoAction, *m_quitAction, *m_connectAction,
        *m_disconnectAction, *m_settingsAction, *m_unitConfigAction, *m_runFromLineAction,
        *m_wholeProgramAction, *m_aboutAction, *m_shortcutsAction,
        *m_grinderAction = nullptr, *m_resetLayoutAction, *m_toolTableAction, *m_saveTraceAction,
        *m_commissionAction = nullptr, *m_heightMapAction = nullptr, *m_probeZeroAction = nullptr,
        *m_heightMapViewAction = nullptr;
    QMenu *m_heightMapScaleMenu = nullptr;
    std::vector<std::pair<QAction *, double>> m_heightMapScaleActions; // View › Height map Z
    ProgramSession *m_program;
    QFileSystemWatcher *m_watcher; // the loaded program's file
    bool m_reloadAfterJob = false; // it changed while its job ran: ask when the job ends
    QDateTime m_programModified;   // the file's time when it was read
    driver::MachineController *m_controller = nullptr;
    HoldBanner *m_hold = nullptr;
    PlacementBar *m_placement = nullptr;
    session::WorkOffsets *m_offsets;
    session::MachineLink *m_link = nullptr;
    session::VirtualClockLink *m_virtualClock = nullptr; // Clock::Virtual only
    MainWindowOptions::Clock m_clock = MainWindowOptions::Clock::Real;
    session::RunWorkflow *m_workflow = nullptr;
    std::unique_ptr<session::ProbeFollow> m_follow; // the loaded program probes for itself
    std::shared_ptr<const session::InterpretRequest> m_followRequest; // what m_follow was made of
    session::ConsoleSession *m_consoleSession = nullptr;
    // Rendering of the running job: the actual speed from the live position; the hold shown.
    ActualSpeed m_speed;
    ActualSpeed m_panelSpeed{1.0};      // the status panel's, smoothed over a second
    session::RemainingTime m_remaining; // the planner's time left, from the job's start
    // The program's modes for the status panel, read on as the job's line grows.
    std::unique_ptr<session::ModalScanner> m_modes;
    const void *m_modesText = nullptr; // the program text it reads
    int m_modesSystem = 0;             // the coordinate system it starts in
    int m_holdLine = 0;
    QString m_holdDetail;
    QString m_lastError;
    QString m_profilePath;
    QPointer<SettingsDialog> m_settings;
    QPointer<UnitConfigDialog> m_unitConfig;
    QPointer<ProgramInfoDialog> m_programInfo;
    QPointer<ToolTableDialog> m_toolTable;
    QPointer<HeightMapDialog> m_heightMap;
    QPointer<class ProbeZeroDialog> m_probeZero;
    QPointer<QWidget> m_grinder;
    QByteArray m_defaultState;
};

// The state of the machine in the user's words ("Ready", "Tool lifted").
QString machineModeText(driver::MachineMode mode);

} // namespace frezka::gui
