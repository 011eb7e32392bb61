#pragma once
// Helpers the main-window tests share: a window unconnected or on the built-in emulator with
// its settings apart, a program written to a temporary directory and opened in the window, a
// button found by its object name, what the emulator counted or received.

#include "driver/emulator/unit.h"
#include "driver/link/machinecontroller.h"
#include "gui/mainwindow.h"
#include "gui/programview.h"
#include "machine/machineconfig.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QFile>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

namespace frezka::gui::test {

// Writes text to name in dir; the file's path, empty when it cannot be written.
inline QString writeProgram(const QTemporaryDir &dir, const QString &name, const QByteArray &text)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(text);
    return path;
}

// Opens the program in the window; true once it has loaded.
inline bool openAndWait(MainWindow *window, const QString &path)
{
    QSignalSpy loaded(window->program(), &ProgramSession::loaded);
    window->openProgram(path);
    return loaded.wait(20000);
}

// The window's settings (and QStandardPaths) in dir under the organisation's name, apart from
// the user's and from other tests'.
inline void isolateSettings(const QTemporaryDir &dir, const QString &organisation)
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir.path());
    QCoreApplication::setOrganizationName(organisation);
}

// Saves the profile as dir/machine.json and makes it the window's last profile; false when it
// cannot be written.
inline bool useProfile(const QTemporaryDir &dir, const machine::MachineConfig &profile)
{
    const QString profilePath = dir.filePath(QStringLiteral("machine.json"));
    if (machine::saveMachineConfig(profile, profilePath.toStdString()))
        return false;
    QSettings().setValue(QStringLiteral("lastProfile"), profilePath);
    return true;
}

// A main window with the software view and the default layout, shown.
inline std::unique_ptr<MainWindow> shownWindow()
{
    MainWindowOptions options;
    options.view = MainWindowOptions::View::Software;
    options.restoreLayout = false;
    auto window = std::make_unique<MainWindow>(options);
    window->show();
    return window;
}

// A main window on the default GVE64 profile whose port does not exist, its settings in dir
// under the organisation's name: its own link stays unconnected while the test drives a
// simulated one and the window shows it. Shown, once it has said the port is missing; null when
// it cannot be set up.
inline std::unique_ptr<MainWindow> unconnectedWindow(const QTemporaryDir &dir,
                                                     const QString &organisation)
{
    isolateSettings(dir, organisation);
    QSettings().setValue(QStringLiteral("link/autoReconnect"), false);
    machine::MachineConfig profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
    profile.link.port = dir.filePath(QStringLiteral("no-such-port")).toStdString();
    if (!useProfile(dir, profile))
        return nullptr;
    auto window = shownWindow();
    if (!QTest::qWaitFor([&] { return !window->lastError().isEmpty(); }, 20000))
        return nullptr;
    return window;
}

// A main window on the built-in emulator (the default profile, or `profile` when given), its
// settings in dir under the organisation's name, the emulated work's surface as
// FREZKA_EMULATOR_SURFACE gives it (docs/emulator.md; empty: none). Shown, once the unit is
// connected and idle; null when it cannot be set up.
inline std::unique_ptr<MainWindow> emulatorWindow(const QTemporaryDir &dir, const char *surface,
                                                  const QString &organisation,
                                                  const machine::MachineConfig *profile = nullptr)
{
    if (surface && *surface)
        qputenv("FREZKA_EMULATOR_SURFACE", surface);
    else
        qunsetenv("FREZKA_EMULATOR_SURFACE");
    isolateSettings(dir, organisation);
    if (profile && !useProfile(dir, *profile))
        return nullptr;
    auto window = shownWindow();
    if (!QTest::qWaitFor(
            [&] { return window->controller()->state().mode == driver::MachineMode::Idle; }, 30000))
        return nullptr;
    return window;
}

// What the window's built-in emulator has counted so far (its machine unit); a default (all
// zero, vectorsExecuted -1) when the window is not on it, so that a comparison fails.
inline emulator::Stats emulatorStats(MainWindow *window)
{
    if (auto stats = window->controller()->builtInEmulatorStats())
        return *stats;
    emulator::Stats none;
    none.motion.vectorsExecuted = -1;
    return none;
}

inline QPushButton *button(QWidget *parent, const char *name)
{
    return parent->findChild<QPushButton *>(QLatin1String(name));
}

// What gve-emu has received so far: the "pc>" lines of its --verbose log on stderr (read into
// `log` as they come), joined.
inline QByteArray emulatorReceived(QProcess &emu, QByteArray &log)
{
    log += emu.readAllStandardError();
    QByteArray in;
    for (const QByteArray &line : log.split('\n')) {
        const auto at = line.indexOf(" pc> ");
        if (at >= 0)
            in += line.mid(at + 5).replace("\\r", "\r");
    }
    return in;
}

} // namespace frezka::gui::test
