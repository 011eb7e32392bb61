#include "language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace frezka::gui {
namespace {

QTranslator *g_app = nullptr;
QTranslator *g_qt = nullptr;
QString g_current;

} // namespace

QStringList availableLanguages()
{
    return {QStringLiteral("cs"), QStringLiteral("en")};
}

QString effectiveLanguage(const QString &setting)
{
    if (availableLanguages().contains(setting))
        return setting;
    const QString system = QLocale::system().name().section(QLatin1Char('_'), 0, 0);
    return availableLanguages().contains(system) ? system : QStringLiteral("en");
}

bool applyLanguage(const QString &code)
{
    auto *app = QCoreApplication::instance();
    if (!g_app) {
        g_app = new QTranslator(app);
        g_qt = new QTranslator(app);
    }
    QCoreApplication::removeTranslator(g_app);
    QCoreApplication::removeTranslator(g_qt);
    const bool ok = g_app->load(QStringLiteral(":/i18n/frezka_%1.qm").arg(code));
    if (ok)
        QCoreApplication::installTranslator(g_app);
    if (g_qt->load(QStringLiteral("qtbase_%1").arg(code),
                   QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(g_qt);
    g_current = ok ? code : QStringLiteral("en");
    return ok;
}

QString currentLanguage()
{
    return g_current;
}

} // namespace frezka::gui
