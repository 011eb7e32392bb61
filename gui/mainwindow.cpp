#include "mainwindow.h"

#include "consolewidget.h"
#include "drowidget.h"
#include "iopanel.h"
#include "jogpanel.h"
#include "language.h"
#include "loadprogress.h"
#include "outputspanel.h"
#include "profilestore.h"
#include "programlisting.h"
#include "programview.h"
#include "runpanel.h"
#include "settingsdialog.h"
#include "shortcuts.h"
#include "statuspanel.h"
#include "unitconfigdialog.h"

#include "driver/link/machinecontroller.h"
#ifdef FREZKA_HAVE_GRINDER_GUI
#include "gui/grinder/grinderwindow.h"
#endif
#include "speedplot.h"
#include "toolpathview.h"

#include "protocol/variant.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QKeyEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QSettings>
#include <QStatusBar>
#include <QVBoxLayout>

namespace frezka::gui {
namespace {
constexpr int kMaxRecent = 8;
}

MainWindow::MainWindow(const MainWindowOptions &options, QWidget *parent)
    : QMainWindow(parent)
    , m_clock(options.clock)
{
    setObjectName(QStringLiteral("frezkaMainWindow"));
    using B = ToolpathView::Backend;
    const B backend = options.view == MainWindowOptions::View::Software ? B::Software
                      : options.view == MainWindowOptions::View::OpenGl ? B::OpenGl
                                                                        : B::Auto;
    m_view = new ToolpathView(this, backend);
    buildCentral();
    m_program = new ProgramSession(this);
    m_watcher = new QFileSystemWatcher(this);
    connect(m_watcher, &QFileSystemWatcher::fileChanged, this, &MainWindow::onProgramFileChanged);
    m_offsets = new session::WorkOffsets(this);
    m_program->setViewBuilder(sceneBuilder(m_view->preferredMaxSegments(), m_view->usesOpenGl()));

    buildDocks();
    buildMenus();
    auto *sb = statusBar();
    m_connection = new QLabel(this);
    m_connection->setObjectName(QStringLiteral("connectionStatus"));
    m_unit = new QLabel(this);
    m_state = new QLabel(this);
    m_state->setObjectName(QStringLiteral("machineStatus"));
    m_file = new QLabel(this);
    m_file->setObjectName(QStringLiteral("programFile"));
    m_file->setMinimumWidth(260); // file name changes should not relayout the window
    m_io = new IoPanel(this);
    m_loadProgress = new LoadProgress(this);
    m_loadProgress->setObjectName(QStringLiteral("loadProgress"));
    m_loadProgress->setVisible(false);
    sb->addWidget(m_connection);
    sb->addWidget(m_unit);
    sb->addWidget(m_state);
    sb->addWidget(m_io);
    sb->addPermanentWidget(m_loadProgress);
    sb->addPermanentWidget(m_file);

    connectProgram();
    connectLoadCancel();
    connectMachine();
    connectProbeFollow();
    retranslate();
    resize(1366, 740);
    m_defaultState = saveState();
    if (options.restoreLayout) {
        QSettings s;
        restoreGeometry(s.value(QStringLiteral("window/geometry")).toByteArray());
        restoreState(s.value(QStringLiteral("window/state")).toByteArray());
    }
    updateRecentMenu();
    applyDisplayUnits();
    const ProfileLoad profile = loadCurrentProfile();
    applyProfile(profile.config, profile.path);
    for (const QString &notice : profile.notices)
        m_console->appendInfo(notice);
    if (!profile.error.isEmpty())
        QMetaObject::invokeMethod(
            this, [this, e = profile.error] { showError(e); }, Qt::QueuedConnection);
    updateRunPhase();
}

MainWindow::~MainWindow()
{
    if (m_workflow)
        m_workflow->setProbeFollow(nullptr); // m_follow goes before the workflow
}

void MainWindow::buildDocks()
{
    auto dock = [this](QWidget *w, const char *name, Qt::DockWidgetArea area) {
        auto *d = new QDockWidget(this);
        d->setObjectName(QLatin1String(name));
        d->setWidget(w);
        d->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable |
                       QDockWidget::DockWidgetClosable);
        addDockWidget(area, d);
        return d;
    };
    m_dro = new DroWidget(this);
    m_run = new RunPanel(this);
    m_jog = new JogPanel(this);
    m_outputs = new OutputsPanel(this);
    m_listing = new ProgramListing(this);
    m_console = new ConsoleWidget(this);
    m_plot = new SpeedPlot(this);
    m_status = new StatusPanel(this);
    m_statusDock = dock(m_status, "statusDock", Qt::RightDockWidgetArea);
    m_droDock = dock(m_dro, "droDock", Qt::LeftDockWidgetArea);
    m_runDock = dock(m_run, "runDock", Qt::LeftDockWidgetArea);
    m_jogDock = dock(m_jog, "jogDock", Qt::LeftDockWidgetArea);
    m_outputsDock = dock(m_outputs, "outputsDock", Qt::LeftDockWidgetArea);
    tabifyDockWidget(m_jogDock, m_outputsDock);
    m_jogDock->raise();
    m_programDock = dock(m_listing, "programDock", Qt::RightDockWidgetArea);
    splitDockWidget(m_statusDock, m_programDock, Qt::Vertical);
    m_consoleDock = dock(m_console, "consoleDock", Qt::BottomDockWidgetArea);
    m_plotDock = dock(m_plot, "plotDock", Qt::BottomDockWidgetArea);
    tabifyDockWidget(m_consoleDock, m_plotDock);
    m_consoleDock->raise();
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    resizeDocks({m_droDock}, {380}, Qt::Horizontal);
    resizeDocks({m_programDock}, {300}, Qt::Horizontal);
    resizeDocks({m_consoleDock}, {150}, Qt::Vertical);
}

void MainWindow::buildMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_openAction = m_fileMenu->addAction(QString(), this, &MainWindow::openDialog);
    m_openAction->setShortcut(QKeySequence::Open);
    m_reloadAction = m_fileMenu->addAction(QString(), this, &MainWindow::reloadProgram);
    m_reloadAction->setObjectName(QStringLiteral("reloadProgram"));
    m_reloadAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R)); // AXIS's
    m_reloadAction->setEnabled(false);
    m_infoAction = m_fileMenu->addAction(QString(), this, [this] { openProgramInfo(); });
    m_infoAction->setObjectName(QStringLiteral("programInfo"));
    m_infoAction->setEnabled(false);
    m_recentMenu = m_fileMenu->addMenu(QString());
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    m_fileMenu->addSeparator();
    m_quitAction = m_fileMenu->addAction(QString(), this, &QWidget::close);
    m_quitAction->setShortcut(QKeySequence::Quit);

    m_machineMenu = menuBar()->addMenu(QString());
    m_connectAction = m_machineMenu->addAction(QString(), this, [this] { connectToUnit(); });
    m_disconnectAction =
        m_machineMenu->addAction(QString(), this, [this] { disconnectFromUnit(); });
    m_machineMenu->addSeparator();
    m_settingsAction = m_machineMenu->addAction(QString(), this, [this] { openSettings(); });
    m_unitConfigAction = m_machineMenu->addAction(QString(), this, [this] { openUnitConfig(); });
    buildToolTableAction();
    buildHeightMapAction();
    buildFromLineActions();
    buildTraceAction();
    buildCommissionAction();

    m_viewMenu = menuBar()->addMenu(QString());
    for (auto *d : {m_statusDock, m_droDock, m_runDock, m_jogDock, m_outputsDock, m_programDock,
                    m_consoleDock, m_plotDock})
        m_viewMenu->addAction(d->toggleViewAction());
    m_viewMenu->addSeparator();
    buildHeightMapViewActions();
    m_viewMenu->addSeparator();
    m_resetLayoutAction =
        m_viewMenu->addAction(QString(), this, [this] { restoreState(m_defaultState); });

    m_toolsMenu = menuBar()->addMenu(QString());
#ifdef FREZKA_HAVE_GRINDER_GUI
    m_grinderAction = m_toolsMenu->addAction(QString(), this, [this] {
        if (!m_grinder) {
            m_grinder = new GrinderWindow(); // a window of its own, not tied to the machine
            m_grinder->setAttribute(Qt::WA_DeleteOnClose);
        }
        m_grinder->show();
        m_grinder->raise();
    });
#endif
    m_toolsMenu->menuAction()->setVisible(m_grinderAction != nullptr);
    m_helpMenu = menuBar()->addMenu(QString());
    m_shortcutsAction =
        m_helpMenu->addAction(QString(), this, [this] { showShortcutsDialog(this); });
    m_shortcutsAction->setObjectName(QStringLiteral("keyboardShortcuts"));
    m_aboutAction = m_helpMenu->addAction(QString(), this, [this] {
        QMessageBox::about(this, tr("About Frezka"),
                           tr("<b>Frezka %1</b><br>Runs CNC mills through GVE interpolators.")
                               .arg(QCoreApplication::applicationVersion()));
    });
}

void MainWindow::retranslate()
{
    setWindowTitle(m_program->program().path.isEmpty()
                       ? tr("Frezka")
                       : tr("Frezka — %1").arg(QFileInfo(m_program->program().path).fileName()));
    m_statusDock->setWindowTitle(tr("Status"));
    m_droDock->setWindowTitle(tr("Position"));
    m_runDock->setWindowTitle(tr("Program run"));
    m_jogDock->setWindowTitle(tr("Jog and homing"));
    m_outputsDock->setWindowTitle(tr("Spindle and outputs"));
    m_programDock->setWindowTitle(tr("Program"));
    m_consoleDock->setWindowTitle(tr("Console"));
    m_plotDock->setWindowTitle(tr("Speed"));
    m_fileMenu->setTitle(tr("&File"));
    m_openAction->setText(tr("&Open program…"));
    m_reloadAction->setText(tr("Re&load program"));
    m_infoAction->setText(tr("Program &info…"));
    m_recentMenu->setTitle(tr("Open &recent"));
    m_quitAction->setText(tr("&Quit"));
    m_machineMenu->setTitle(tr("&Machine"));
    m_connectAction->setText(tr("&Connect"));
    m_disconnectAction->setText(tr("&Disconnect"));
    m_settingsAction->setText(tr("&Settings…"));
    m_unitConfigAction->setText(tr("&Unit configuration (EEPROM)…"));
    m_toolTableAction->setText(tr("&Tool table…"));
    m_heightMapAction->setText(tr("&Height map…"));
    m_probeZeroAction->setText(tr("&Probe work zero…"));
    m_runFromLineAction->setText(tr("Run from &line…"));
    m_wholeProgramAction->setText(tr("Run the &whole program"));
    m_saveTraceAction->setText(tr("Save serial &trace…"));
    m_commissionAction->setText(tr("C&ommission this machine…"));
    m_viewMenu->setTitle(tr("&View"));
    m_resetLayoutAction->setText(tr("&Reset layout"));
    retranslateHeightMapView();
    m_toolsMenu->setTitle(tr("&Tools"));
    if (m_grinderAction)
        m_grinderAction->setText(tr("&Grinder transfer (ANC/K51)…"));
    m_helpMenu->setTitle(tr("&Help"));
    m_shortcutsAction->setText(tr("&Keyboard shortcuts"));
    m_aboutAction->setText(tr("&About Frezka"));
    if (m_program->program().path.isEmpty())
        m_file->setText(tr("No program"));
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        if (m_link) { // the hold's words and the connection in the new language
            m_holdDetail.clear();
            onState(m_link->state());
        }
    }
    QMainWindow::changeEvent(event);
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    // Quit closes everything: the grinder window first (it may ask about unsaved data).
    if (m_grinder && !m_grinder->close()) {
        event->ignore();
        return;
    }
    QSettings s;
    s.setValue(QStringLiteral("window/geometry"), saveGeometry());
    s.setValue(QStringLiteral("window/state"), saveState());
    m_program->cancel();
    event->accept();
}

void MainWindow::showError(const QString &message)
{
    m_lastError = message;
    m_console->appendError(message);
    statusBar()->showMessage(message, 15000);
    emit errorShown(message);
    // Never modal under the offscreen platform (tests) — the console and status bar show it.
    if (QGuiApplication::platformName() != QLatin1String("offscreen")) {
        auto *box =
            new QMessageBox(QMessageBox::Warning, tr("Frezka"), message, QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    }
}

// ---- program ----

void MainWindow::openDialog()
{
    QSettings s;
    const QString dir = s.value(QStringLiteral("program/lastDir")).toString();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open program"), dir,
                                     tr("G-code (*.nc *.ngc *.gcode *.tap *.txt);;All files (*)"));
    if (!path.isEmpty()) {
        s.setValue(QStringLiteral("program/lastDir"), QFileInfo(path).absolutePath());
        openProgram(path);
    }
}

void MainWindow::openProgram(const QString &path)
{
    // The renderer may only now know what it runs on (GL initialises on first show).
    m_program->setViewBuilder(sceneBuilder(m_view->preferredMaxSegments(), m_view->usesOpenGl()));
    m_program->setStartLine(0); // a new program runs whole
    m_programModified = QFileInfo(path).lastModified();
    m_program->load(path);
}

void MainWindow::addRecent(const QString &path)
{
    QSettings s;
    QStringList recent = s.value(QStringLiteral("recentFiles")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    s.setValue(QStringLiteral("recentFiles"), recent);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu()
{
    m_recentMenu->clear();
    const QStringList recent = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    for (const QString &path : recent)
        m_recentMenu->addAction(path, this, [this, path] { openProgram(path); });
    m_recentMenu->setEnabled(!recent.isEmpty());
}

void MainWindow::connectProgram()
{
    connect(m_program, &ProgramSession::loadStarted, this, [this](const QString &path) {
        m_loadProgress->setProgress(0, QString());
        m_loadProgress->setVisible(true);
        m_file->setText(tr("Loading %1…").arg(QFileInfo(path).fileName()));
    });
    connect(m_program, &ProgramSession::loadProgress, this,
            [this](double f, const QString &stage) { m_loadProgress->setProgress(f, stage); });
    connect(m_program, &ProgramSession::loadFailed, this, [this](const QString &why) {
        m_loadProgress->setVisible(false);
        m_file->setText(tr("No program"));
        showError(why);
    });
    connect(m_program, &ProgramSession::loaded, this, [this] {
        m_loadProgress->setVisible(false);
        const LoadedProgram &p = m_program->program();
        m_listing->setText(p.text);
        m_view->model()->setScene(sceneOf(p));
        if (p.errors.empty()) { // a good file: the previous file's error is no longer news
            m_lastError.clear();
            statusBar()->clearMessage();
        }

        m_plot->setPlanned(p.speed);
        checkProgramLimits();
        updatePlacement();
        m_run->setProgress(0, 0, p.estimatedS);
        m_file->setText(programFileText());
        retranslate();
        addRecent(p.path);
        m_reloadAction->setEnabled(true);
        m_infoAction->setEnabled(true);
        updateProgramInfo();
        if (m_watcher->files() != QStringList{p.path}) {
            if (!m_watcher->files().isEmpty())
                m_watcher->removePaths(m_watcher->files());
            m_watcher->addPath(p.path);
        }
        for (const auto &w : p.warnings)
            m_console->appendInfo(w.text);
        onFromLineLoaded();
        if (!p.errors.empty()) {
            std::set<int> lines;
            for (const auto &e : p.errors)
                lines.insert(e.line);
            m_listing->setErrorLines(lines);
            m_listing->showErrorLine(p.errors.front().line);
            for (std::size_t i = 1; i < p.errors.size(); ++i)
                m_console->appendError(p.errors[i].text);
            showError(tr("The program has %n error(s); nothing will run until they are fixed.\n%1",
                         nullptr, int(p.errors.size()))
                          .arg(p.errors.front().text));
        }
        updateRunPhase();
    });
}

SettingsDialog *MainWindow::openSettings()
{
    if (!m_settings) {
        m_settings = new SettingsDialog(profile(), m_profilePath, this);
        m_settings->setAttribute(Qt::WA_DeleteOnClose);
        connect(m_settings, &SettingsDialog::profileApplied, this, &MainWindow::applyProfile);
        connect(m_settings, &SettingsDialog::shortcutsChanged, this,
                &MainWindow::applyShortcutKeys);
        connect(m_settings, &SettingsDialog::displayUnitsChanged, this,
                &MainWindow::applyDisplayUnits);
    }
    m_settings->show();
    m_settings->raise();
    return m_settings;
}

UnitConfigDialog *MainWindow::openUnitConfig()
{
    if (!m_unitConfig) {
        m_unitConfig = new UnitConfigDialog(m_controller, profile(), this);
        m_unitConfig->setAttribute(Qt::WA_DeleteOnClose);
    }
    m_unitConfig->show();
    m_unitConfig->raise();
    return m_unitConfig;
}

void MainWindow::applyProfile(const machine::MachineConfig &config, const QString &path)
{
    const bool newLink =
        m_workflow->connectionAsked() &&
        (config.link.port != profile().link.port || config.link.baud != profile().link.baud);
    m_workflow->setProfile(config); // the controller's too
    if (newLink) {
        // A new port (or rate) set with Apply is used now, unless a job is on the machine.
        if (m_link->state().jobActive)
            m_console->appendInfo(tr("The new port is used when you connect again after the "
                                     "job."));
        else
            QMetaObject::invokeMethod(
                this, [this] { connectToUnit(); }, Qt::QueuedConnection);
    }
    m_profilePath = path;
    const auto &info = protocol::variantInfo(config.unit.variant);
    const int axes = info.axisCount == 4 && config.axes[3].present ? 4 : 3;
    m_dro->setAxisCount(axes);
    m_jog->setAxisCount(axes);
    m_jog->setMpgAvailable(
        protocol::featuresOf(config.unit.variant, config.unit.firmwareVersion).mpg);
    m_io->setRelayCount(info.relayOutputs);
    m_outputs->setMaxRpm(config.spindle.maxRpm);
    using F = machine::OutputFunction;
    static const std::pair<F, const char *> kExtra[] = {
        {F::Laser, QT_TR_NOOP("Laser")},
        {F::CoverLock, QT_TR_NOOP("Cover lock")},
        {F::ToolRelease, QT_TR_NOOP("Tool release")},
        {F::ToolCoverOpen, QT_TR_NOOP("Tool cover")}};
    std::vector<std::pair<QString, machine::OutputFunction>> extra;
    for (const auto &[function, name] : kExtra) {
        if (machine::outputNumber(config, function) >= 0) // an output carries it
            extra.emplace_back(tr(name), function);
    }
    m_outputs->setExtraOutputs(extra);
    SceneBounds travel;
    travel.valid = true;
    for (int i = 0; i < 3; ++i) {
        const auto &a = config.axes[std::size_t(i)];
        travel.min[i] = float(a.softMinMm);
        travel.max[i] = float(a.softMaxMm);
    }
    m_view->model()->setTravelBox(travel);
    m_program->setProfile(config);
    loadToolTable();
    if (m_unitConfig)
        m_unitConfig->setProfile(config);
    if (!m_program->program().path.isEmpty())
        m_program->reload(); // re-plan for the new profile
    m_unit->setText(QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size())));
    checkProgramLimits();
}

void MainWindow::checkProgramLimits()
{
    const auto scene = sceneOf(m_program->program());
    if (!scene || !scene->bounds.valid) {
        m_view->model()->setBoundsOutsideLimits(false);
        return;
    }
    bool outside = false;
    for (int i = 0; i < 3; ++i) {
        const auto &a = profile().axes[std::size_t(i)];
        if (!a.present)
            continue;
        outside = outside || scene->bounds.min[i] < a.softMinMm - 1e-6 ||
                  scene->bounds.max[i] > a.softMaxMm + 1e-6;
    }
    m_view->model()->setBoundsOutsideLimits(outside);
}

// ---- keyboard jog ----

void MainWindow::keyPressEvent(QKeyEvent *event)
{
    if (!jogKey(event, true))
        QMainWindow::keyPressEvent(event);
}

void MainWindow::keyReleaseEvent(QKeyEvent *event)
{
    if (!jogKey(event, false))
        QMainWindow::keyReleaseEvent(event);
}

} // namespace frezka::gui
