#include "app/registry/builtin_registry.h"
#include "app/registry/family_parts.h"
#include "cambench_version.h"
#include "comm/device/protocol_registry.h"
#include "ui/gui_settings.h"
#include "ui/language.h"
#include "ui/main_window.h"
#include "ui/screenshot_tour.h"
#include "ui/shell.h"
#include "ui/theme.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>

namespace {

// The command line of cambench; the same for the text-only run (--help,
// --version) and the real one.
struct CommandLine {
    QCommandLineParser parser;
    const QCommandLineOption lang{QStringLiteral("lang"),
                                  QStringLiteral("User interface language: de or en."),
                                  QStringLiteral("language")};
    const QCommandLineOption dark{QStringLiteral("dark"), QStringLiteral("Use the dark palette.")};
    const QCommandLineOption port{
        QStringLiteral("port"),
        QStringLiteral("Connect to this port at start (serial port, tcp://host:port, sim)."),
        QStringLiteral("port")};
    const QCommandLineOption protocol{
        QStringLiteral("protocol"),
        QStringLiteral("With --port: a protocol id, as `cambench-cli --help` lists them "
                       "(default: the connection page's choice)."),
        QStringLiteral("protocol")};
    const QCommandLineOption machine{
        QStringLiteral("machine"),
        QStringLiteral("Open the machine of this machine file beside the window (as File → Open "
                       "machine… does)."),
        QStringLiteral("FILE")};
    const QCommandLineOption shots{QStringLiteral("screenshots"),
                                   QStringLiteral("Visit every screen of every family and "
                                                  "protocol on its simulated device, save one "
                                                  "PNG each into DIR, and exit."),
                                   QStringLiteral("DIR")};

    CommandLine() {
        parser.setApplicationDescription(
            QStringLiteral("Programming, monitoring and backup of machine controllers.\n"
                           "Version " CAMBENCH_VERSION_TEXT "."));
        parser.addHelpOption();
        parser.addVersionOption();
        parser.addOptions({lang, dark, port, protocol, machine, shots});
    }
};

// --help and --version print text: no display is needed for that (a
// technician on ssh, a packaging check), so no QApplication is made.
bool onlyText(int argc, char* argv[]) {
    for (int i = 1; i < argc; ++i) {
        const QByteArray arg(argv[i]);
        if (arg == "--help" || arg == "-h" || arg == "-?" || arg == "--help-all" ||
            arg == "--version" || arg == "-v")
            return true;
    }
    return false;
}

void nameApplication() {
    QCoreApplication::setOrganizationName(QStringLiteral("CamBench"));
    QCoreApplication::setApplicationName(QStringLiteral("CamBench"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CAMBENCH_VERSION_TEXT));
}

}  // namespace

int main(int argc, char* argv[]) {
    cambench::registerBuiltins();
    if (!cambench::familiesComplete(cambench::Program::Gui, "cambench"))
        return 70;  // EX_SOFTWARE: this build lacks a family's part
    if (onlyText(argc, argv)) {
        QCoreApplication text(argc, argv);
        nameApplication();
        CommandLine commandLine;
        commandLine.parser.process(text);  // prints and exits
        return 0;
    }
    QApplication app(argc, argv);
    nameApplication();

    CommandLine commandLine;
    QCommandLineParser& parser = commandLine.parser;
    const QCommandLineOption& lang = commandLine.lang;
    const QCommandLineOption& dark = commandLine.dark;
    const QCommandLineOption& port = commandLine.port;
    const QCommandLineOption& protocol = commandLine.protocol;
    const QCommandLineOption& shots = commandLine.shots;
    const QCommandLineOption& machine = commandLine.machine;
    parser.process(app);

    // The screenshot tour shows the program as first started and must not
    // overwrite what the user's CamBench remembers: its own, empty settings.
    QTemporaryDir tourSettings;
    if (parser.isSet(shots)) {
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, tourSettings.path());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, tourSettings.path());
    }

    // The command line first, then what the user chose last time, then the system's.
    QString language = parser.isSet(lang) ? parser.value(lang) : cambench::guisettings::language();
    if (language.isEmpty()) language = cambench::systemLanguage();
    if (language != QLatin1String("de") && language != QLatin1String("en")) {
        std::fprintf(stderr, "cambench: unknown language '%s'; use de or en.\n",
                     qPrintable(language));
        return 2;
    }
    cambench::setLanguage(language);
    cambench::applyTheme(parser.isSet(dark) || cambench::guisettings::dark().value_or(false));

    // The port given, else the last connection that worked (empty: the
    // shell takes it), else the simulated device with its demo program. The
    // screenshot tour connects to its devices itself (and, with its own
    // empty settings, the shell to nothing).
    QString startPort = parser.value(port);
    if (!parser.isSet(shots) && startPort.isEmpty() && !cambench::guisettings::loadConnection())
        startPort = QStringLiteral("sim");
    if (parser.isSet(shots)) startPort.clear();
    const QString startProtocol = parser.value(protocol);
    if (!startProtocol.isEmpty() &&
        !cambench::comm::ProtocolRegistry::instance().find(startProtocol)) {
        std::fprintf(stderr, "cambench: unknown protocol '%s'; use one of %s.\n",
                     qPrintable(startProtocol),
                     qPrintable(cambench::comm::ProtocolRegistry::instance().idList()));
        return 2;
    }
    cambench::Shell shell;
    shell.start(startPort, startProtocol);
    if (parser.isSet(machine)) {
        const cambench::Result<cambench::Machine*> opened =
            shell.openMachineFile(parser.value(machine));
        if (!opened) {
            std::fprintf(stderr, "cambench: %s\n", qPrintable(opened.error().message));
            return 2;
        }
    }

    if (parser.isSet(shots)) {
        auto* tour = new cambench::ScreenshotTour(&shell, parser.value(shots), &shell);
        QObject::connect(tour, &cambench::ScreenshotTour::finished, &app, [tour](bool ok) {
            for (const QString& failure : tour->failures())
                std::fprintf(stderr, "cambench: %s\n", qPrintable(failure));
            QCoreApplication::exit(ok ? 0 : 1);
        });
        QTimer::singleShot(0, tour, [tour] { tour->start(); });
    }
    return app.exec();
}
