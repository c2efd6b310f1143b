// Issue 39, item 4: one way to give options. parseGlobalOptions
// (app/cli/cli_options.h) with the built-in families' protocols and
// transports, and command groups registered here as the families register
// theirs (the real ones are cambench-cli's: tst_e2e_cli runs them): every
// option before or after the command; the family the command, a family's
// option, --address, --protocol or the port names; two that disagree are an
// error naming both; a line command speaks Multiuser unless told otherwise.
#include "app/cli/cli_options.h"
#include "app/cli/commands.h"

#include <QTest>

using namespace cambench;
using namespace cambench::cli;

namespace {

int runNothing(CliSession&, CommandArgs&) {
    return 0;
}

// The error's message, or "" when `args` parsed.
QString errorOf(const QStringList& args) {
    const Result<GlobalOptions> parsed = parseGlobalOptions(args);
    return parsed ? QString() : parsed.error().message;
}

}  // namespace

class TestCliOptions : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        CommandRegistry& registry = CommandRegistry::instance();
        registry.add({QStringLiteral("camcon"), QStringLiteral("info"), runNothing});
        registry.add({QStringLiteral("camcon"), QStringLiteral("verify-line"), runNothing,
                      QStringLiteral("multiuser")});
        registry.add({QStringLiteral("mc1"), QStringLiteral("mc"), runNothing});
        registry.add({QStringLiteral("compax3"), QStringLiteral("c3"), runNothing});
        registry.add({{}, QStringLiteral("machine"), runNothing});
        registry.addOption({QStringLiteral("mc1"), QStringLiteral("--axes")});
        registry.addOption({QStringLiteral("compax3"), QStringLiteral("--dictionary")});
    }

    // The same options before and after the command mean the same; the
    // family's own options reach the command, after its words.
    void optionsBeforeOrAfterTheCommand() {
        const QStringList options = {"--port", "/dev/ttyUSB3", "--variant", "mc100v1",
                                     "--axes", "1,2",          "--timeout", "500"};
        const QStringList command = {"mc", "var", "read", "12"};
        for (const QStringList& args :
             {options + command, command + options,
              QStringList{"--port=/dev/ttyUSB3", "mc", "--variant", "mc100v1", "var", "--axes=1,2",
                          "read", "12", "--timeout", "500"}}) {
            const Result<GlobalOptions> parsed = parseGlobalOptions(args);
            QVERIFY2(parsed, qPrintable(parsed.error().message));
            QCOMPARE(parsed->port, QStringLiteral("/dev/ttyUSB3"));
            QCOMPARE(parsed->family, QStringLiteral("mc1"));
            QCOMPARE(parsed->protocol, QStringLiteral("mc1"));
            QCOMPARE(parsed->protocolSettings()->toMap().value(QStringLiteral("variant")),
                     QStringLiteral("mc100v1"));
            QCOMPARE(parsed->timeoutMs, 500);
            QCOMPARE(parsed->command, QStringLiteral("mc"));
            QCOMPARE(parsed->commandArgs, QStringList({"var", "read", "12", "--axes", "1,2"}));
        }
    }

    // A command's own option before the command is handed to it; its
    // value is the next word unless that is a command.
    void commandOptionsBeforeTheCommand() {
        const Result<GlobalOptions> json = parseGlobalOptions({"--json", "info"});
        QVERIFY2(json, qPrintable(json.error().message));
        QCOMPARE(json->command, QStringLiteral("info"));
        QCOMPARE(json->commandArgs, QStringList({"--json"}));
        const Result<GlobalOptions> file =
            parseGlobalOptions({"-o", "out.json", "--port", "sim", "info", "--json"});
        QVERIFY2(file, qPrintable(file.error().message));
        QCOMPARE(file->command, QStringLiteral("info"));
        QCOMPARE(file->commandArgs, QStringList({"--json", "-o", "out.json"}));
        // Negative numbers and "-" are words, not options.
        const Result<GlobalOptions> words = parseGlobalOptions({"mc", "var", "write", "3", "-5"});
        QVERIFY2(words, qPrintable(words.error().message));
        QCOMPARE(words->commandArgs, QStringList({"var", "write", "3", "-5"}));
    }

    // The family the command, a family's option, --address or --variant
    // names, without --family; the default family without any.
    void theFamilyFollowsFromTheLine() {
        const auto familyAndProtocol = [](const QStringList& args) {
            const Result<GlobalOptions> parsed = parseGlobalOptions(args);
            return parsed ? parsed->family + u' ' + parsed->protocol : parsed.error().message;
        };
        QCOMPARE(familyAndProtocol({"info"}), QStringLiteral("camcon standard"));
        QCOMPARE(familyAndProtocol({"mc", "info"}), QStringLiteral("mc1 mc1"));
        QCOMPARE(familyAndProtocol({"c3", "info"}), QStringLiteral("compax3 compax3"));
        QCOMPARE(familyAndProtocol({"--address", "7", "c3", "info"}),
                 QStringLiteral("compax3 compax3-rs485"));
        QCOMPARE(familyAndProtocol({"c3", "info", "--address", "7"}),
                 QStringLiteral("compax3 compax3-rs485"));
        QCOMPARE(familyAndProtocol({"--dictionary", "my.json", "machine", "status"}),
                 QStringLiteral("compax3 compax3"));
        QCOMPARE(familyAndProtocol({"--variant", "mc200v2", "machine", "status"}),
                 QStringLiteral("mc1 mc1"));
        QCOMPARE(familyAndProtocol({"--protocol", "mc1-ascii", "mc", "info"}),
                 QStringLiteral("mc1 mc1-ascii"));
        // What people typed before stays right.
        QCOMPARE(familyAndProtocol({"--family", "mc1", "mc", "info"}), QStringLiteral("mc1 mc1"));
        QCOMPARE(familyAndProtocol({"--address", "4", "--family", "compax3", "c3", "read"}),
                 QStringLiteral("compax3 compax3-rs485"));
        const Result<GlobalOptions> address = parseGlobalOptions({"--address", "7", "c3", "info"});
        QVERIFY(address);
        QCOMPARE(address->protocolSettings()->device(), 7);
    }

    // A line command speaks Multiuser unless the line says otherwise; a
    // port that names its protocol is spoken to in it.
    void theProtocolFollowsFromTheCommandAndThePort() {
        const auto protocolOf = [](const QStringList& args) {
            const Result<GlobalOptions> parsed = parseGlobalOptions(args);
            return parsed ? parsed->protocol : parsed.error().message;
        };
        QCOMPARE(protocolOf({"verify-line", "line7"}), QStringLiteral("multiuser"));
        QCOMPARE(protocolOf({"--protocol", "cambus", "verify-line", "line7"}),
                 QStringLiteral("cambus"));
        QCOMPARE(protocolOf({"--port", "sim:protocol=3964r-n96;analogue=0", "info"}),
                 QStringLiteral("3964r-n96"));
        QCOMPARE(protocolOf({"--port", "sim:protocol=cambus;devices=3,7", "info"}),
                 QStringLiteral("cambus"));
        QCOMPARE(protocolOf({"--port", "sim:framing=multiuser;devices=0,5", "info"}),
                 QStringLiteral("multiuser"));
        // A port that names nothing is spoken to in the family's default.
        QCOMPARE(protocolOf({"--port", "sim:eprom=03.05.2001;outputs=16", "info"}),
                 QStringLiteral("standard"));
        QCOMPARE(
            protocolOf({"--port", "sim:protocol=3964r-n96", "--protocol", "3964r-n96", "info"}),
            QStringLiteral("3964r-n96"));
    }

    // Two words that name different families, or protocols: an error
    // naming both, before anything is opened.
    void aContradictionNamesBoth() {
        const QString family = errorOf({"--family", "camcon", "mc", "info"});
        QVERIFY2(family.contains(QLatin1String("--family camcon")), qPrintable(family));
        QVERIFY2(family.contains(QLatin1String("\"mc\" is a command of the mc1 family")),
                 qPrintable(family));
        const QString info = errorOf({"--family", "compax3", "info"});
        QVERIFY2(info.contains(QLatin1String("\"info\" is a command of the camcon family")),
                 qPrintable(info));
        const QString protocol = errorOf({"--protocol", "standard", "c3", "info"});
        QVERIFY2(protocol.contains(QLatin1String("--protocol standard")) &&
                     protocol.contains(QLatin1String("compax3")),
                 qPrintable(protocol));
        const QString option = errorOf({"--dictionary", "d.json", "mc", "info"});
        QVERIFY2(option.contains(QLatin1String("--dictionary is an option of the compax3")) &&
                     option.contains(QLatin1String("\"mc\"")),
                 qPrintable(option));
        const QString port =
            errorOf({"--port", "sim:protocol=3964r-n96", "--protocol", "standard", "info"});
        QVERIFY2(port.contains(QLatin1String("sim:protocol=3964r-n96 speaks 3964r-n96")) &&
                     port.contains(QLatin1String("--protocol standard")),
                 qPrintable(port));
        const QString address = errorOf({"--address", "7", "info"});
        QVERIFY2(address.contains(QLatin1String("--address")) &&
                     address.contains(QLatin1String("\"info\"")),
                 qPrintable(address));
    }

    void aCommandLineThatCannotBeUnderstood() {
        QVERIFY(errorOf({}).contains(QLatin1String("no COMMAND")));
        QVERIFY(errorOf({"info", "--port"}).contains(QLatin1String("--port needs a value")));
        QVERIFY(errorOf({"--baud", "fast", "info"}).contains(QLatin1String("--baud")));
        QVERIFY(errorOf({"--family", "s7", "info"}).contains(QLatin1String("s7")));
        // The messages end with what is wrong; where the help is, the
        // caller adds in one line (reportError).
        QVERIFY(!errorOf({"--baud", "fast", "info"}).contains(QLatin1String("--help")));
    }
};

QTEST_GUILESS_MAIN(TestCliOptions)
#include "tst_cli_options.moc"
