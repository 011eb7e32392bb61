#include "profilestore.h"

#include "profilelabels.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace frezka::gui {

QString defaultProfilePath()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppConfigLocation) +
           QStringLiteral("/machine.json");
}

ProfileLoad loadCurrentProfile()
{
    ProfileLoad out;
    out.config = machine::defaultMachineConfig(protocol::Variant::Gve64);
    out.path = QSettings().value(QStringLiteral("lastProfile"), defaultProfilePath()).toString();
    if (!QFileInfo::exists(out.path))
        return out; // first start: defaults, saved on the first "Save"
    const auto result = machine::loadMachineConfig(out.path.toStdString());
    for (const auto &n : result.notes)
        out.notices << configErrorText(n);
    if (result.config) {
        out.config = *result.config;
    } else {
        QStringList lines;
        for (const auto &e : result.errors)
            lines << configErrorText(e);
        out.error = QCoreApplication::translate(
                        "frezka::gui::Profile",
                        "The machine profile %1 cannot be used; the built-in GVE64 defaults "
                        "are active until it is fixed:\n%2")
                        .arg(out.path, lines.join(QLatin1Char('\n')));
    }
    return out;
}

void rememberProfile(const QString &path)
{
    QSettings().setValue(QStringLiteral("lastProfile"), path);
    QDir().mkpath(QFileInfo(path).absolutePath());
}

} // namespace frezka::gui
