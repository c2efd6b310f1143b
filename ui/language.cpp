#include "language.h"

#include "shell_log.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace cambench {

namespace {

QString g_language = QStringLiteral("en");

QTranslator& appTranslator() {
    static QTranslator translator;
    return translator;
}

QTranslator& qtTranslator() {
    static QTranslator translator;
    return translator;
}

}  // namespace

QString systemLanguage() {
    return QLocale::system().language() == QLocale::German ? QStringLiteral("de")
                                                           : QStringLiteral("en");
}

bool setLanguage(const QString& language) {
    QCoreApplication::removeTranslator(&appTranslator());
    QCoreApplication::removeTranslator(&qtTranslator());
    const QString name = language == QLatin1String("de") ? language : QStringLiteral("en");
    if (!appTranslator().load(QStringLiteral(":/i18n/cambench_%1.qm").arg(name))) {
        qCWarning(shellLog) << "no translation catalogue for" << name;
        g_language = QStringLiteral("en");
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        return name == QLatin1String("en");
    }
    QCoreApplication::installTranslator(&appTranslator());
    // Qt's own texts (dialog buttons, context menus); optional.
    if (qtTranslator().load(QStringLiteral("qtbase_%1").arg(name),
                            QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(&qtTranslator());
    g_language = name;
    QLocale::setDefault(name == QLatin1String("de")
                            ? QLocale(QLocale::German, QLocale::Germany)
                            : QLocale(QLocale::English, QLocale::UnitedStates));
    return true;
}

QString currentLanguage() {
    return g_language;
}

}  // namespace cambench
