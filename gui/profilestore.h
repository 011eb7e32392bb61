#pragma once
// Where the machine profile of this installation lives: the last profile used (QSettings
// "lastProfile"), else <AppConfigLocation>/machine.json, else the built-in GVE64 defaults.

#include "machine/machineconfig.h"

#include <QString>
#include <QStringList>

namespace frezka::gui {

struct ProfileLoad
{
    machine::MachineConfig config;
    QString path;  // file it came from / will be saved to
    QString error; // why the file could not be used (config then holds defaults); empty = fine
    QStringList notices; // retired keys read from an older profile (shown in the console)
};

QString defaultProfilePath();
// Loads the profile last used (or the defaults when there is none yet).
ProfileLoad loadCurrentProfile();
// Remembers path as the profile to load next time.
void rememberProfile(const QString &path);

} // namespace frezka::gui
