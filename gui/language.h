#pragma once
// Application language: Czech or English, chosen from the system locale unless the user picked
// one in the settings (QSettings "language": "cs", "en" or empty = system).

#include <QString>
#include <QStringList>

namespace frezka::gui {

// Language codes shipped ("cs", "en").
QStringList availableLanguages();
// The code that applies for a setting ("" = system locale, falls back to English).
QString effectiveLanguage(const QString &setting);
// Installs the translators for the code (replacing earlier ones); widgets get LanguageChange.
// Returns false if the translation could not be loaded (English is always available).
bool applyLanguage(const QString &code);
QString currentLanguage();

} // namespace frezka::gui
