#pragma once
// Helpers the main-window tests share (screen_test, workflow_test): a program written to a
// temporary directory, opened in the window, and a button found by its object name.

#include "gui/mainwindow.h"
#include "gui/programview.h"

#include <QByteArray>
#include <QFile>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>

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
