#pragma once
// Helpers the main-window tests share (screen_test, workflow_test): a program written to a
// temporary directory, opened in the window, and a button found by its object name.

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

// A main window on the default GVE64 profile whose port does not exist, its settings in dir
// under the organisation's name: its own link stays unconnected while the test drives a
// simulated one and the window shows it. Shown, once it has said the port is missing; null when
// it cannot be set up.
inline std::unique_ptr<MainWindow> unconnectedWindow(const QTemporaryDir &dir,
                                                     const QString &organisation)
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir.path());
    QCoreApplication::setOrganizationName(organisation);
    QSettings().setValue(QStringLiteral("link/autoReconnect"), false);
    machine::MachineConfig profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
    profile.link.port = dir.filePath(QStringLiteral("no-such-port")).toStdString();
    const QString profilePath = dir.filePath(QStringLiteral("machine.json"));
    if (machine::saveMachineConfig(profile, profilePath.toStdString()))
        return nullptr;
    QSettings().setValue(QStringLiteral("lastProfile"), profilePath);
    MainWindowOptions options;
    options.view = MainWindowOptions::View::Software;
    options.restoreLayout = false;
    auto window = std::make_unique<MainWindow>(options);
    window->show();
    if (!QTest::qWaitFor([&] { return !window->lastError().isEmpty(); }, 20000))
        return nullptr;
    return window;
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
