#pragma once
// Installs the Czech or English messages embedded under :/i18n/ (see frezka_embed_translations)
// for the user's locale (LANG / LC_*). Headless executables call it right after creating their
// QCoreApplication; the GUI has its own switchable language (gui/language.h).

#include <QCoreApplication>
#include <QLocale>
#include <QTranslator>

namespace frezka::app {

inline void installTranslator()
{
    static QTranslator translator;
    const QString language = QLocale::system().name().section(QLatin1Char('_'), 0, 0);
    if (translator.load(QStringLiteral(":/i18n/frezka_%1.qm").arg(language)))
        QCoreApplication::installTranslator(&translator);
}

} // namespace frezka::app
