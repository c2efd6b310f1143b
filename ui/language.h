#pragma once

#include <QString>

namespace cambench {

// The user interface languages: "en" and "de". The catalogues are built
// from translations/*.ts and embedded as resources (:/i18n/).
QString systemLanguage();
// Installs the catalogues of `language` (and Qt's own for dialog buttons);
// returns false when the language is not available (then English stays).
bool setLanguage(const QString& language);
QString currentLanguage();

}  // namespace cambench
