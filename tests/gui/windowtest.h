#pragma once
// Helpers the main-window tests share (screen_test, workflow_test): a program written to a
// temporary directory, opened in the window, and a button found by its object name.

#include "gui/mainwindow.h"
#include "gui/programsession.h"

#include <QByteArray>
#include <QFile>
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

} // namespace frezka::gui::test
