#pragma once
// Where the shipped data is (machines/*.json, programs/*.nc): the one lookup for every
// executable. An installed executable finds it at <prefix>/share/frezka beside its bin/ folder
// (FREZKA_DATA_FROM_BIN, from GNUInstallDirs), so a package or a `cmake --install --prefix`
// anywhere works without a compiled-in absolute path; an executable in the build tree finds the
// source tree's resources/ (FREZKA_SOURCE_DATA_DIR). Nothing is ever written there: user data
// lives in the XDG locations (QStandardPaths).

#include "app/common/version.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QString>

namespace frezka::app {

// The data folder for an executable in appDir; empty when neither layout is there.
inline QString dataDirFor(const QString &appDir)
{
    const QString installed =
        QDir::cleanPath(appDir + QLatin1Char('/') + QStringLiteral(FREZKA_DATA_FROM_BIN));
    if (QFileInfo(installed + QStringLiteral("/machines")).isDir())
        return installed;
    const QString source = QStringLiteral(FREZKA_SOURCE_DATA_DIR);
    if (QFileInfo(source + QStringLiteral("/machines")).isDir())
        return source;
    return {};
}

inline QString dataDir()
{
    return dataDirFor(QCoreApplication::applicationDirPath());
}

// A machine profile named on the command line: a path as given when it is a file, else a
// shipped profile by name ("gve84" or "gve84.json" -> <data>/machines/gve84.json); the
// argument unchanged when neither exists (the loader then says it cannot open it).
inline QString resolveProfile(const QString &nameOrPath)
{
    if (QFileInfo(nameOrPath).isFile() || nameOrPath.contains(QLatin1Char('/')))
        return nameOrPath;
    const QString data = dataDir();
    if (data.isEmpty())
        return nameOrPath;
    QString file = nameOrPath;
    if (!file.endsWith(QLatin1String(".json")))
        file += QLatin1String(".json");
    const QString shipped = data + QStringLiteral("/machines/") + file;
    return QFileInfo(shipped).isFile() ? shipped : nameOrPath;
}

// "NAME VERSION" and the data folder: what --version prints.
inline QString versionText(const QString &name)
{
    const QString data = dataDir();
    return name + QLatin1Char(' ') + QString::fromUtf8(versionString()) + QLatin1Char('\n') +
           QCoreApplication::translate("frezka::app", "data: %1")
               .arg(data.isEmpty() ? QCoreApplication::translate("frezka::app", "(not found)")
                                   : data) +
           QLatin1Char('\n');
}

} // namespace frezka::app
