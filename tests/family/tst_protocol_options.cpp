// Issue 38, item 1: a protocol declares its options once. A family that
// exists only in the tests (slotted_family.h) brings a protocol with an
// option of its own, "slot" 1..8; registered from here alone, it is offered
// on the connection page, taken by the command line and by a machine file,
// and refused out of its range with its own message. And no file of the
// shell names an option or a protocol of a family; a family's id is one
// constant (item 2).
#include "slotted_family.h"

#include "../ui/shell/shell_fixture.h"

#include "app/cli/cli_options.h"
#include "comm/device/family_registry.h"
#include "comm/device/protocol_options.h"
#include "model/machine/machine_file.h"
#include "ui/connection_page.h"
#include "ui/machine/machine_connection.h"
#include "ui/main_window.h"
#include "ui/shell.h"

#include <QCoreApplication>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QLabel>
#include <QRegularExpression>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <functional>

using namespace cambench;

namespace {

QString errorOf(const QStringList& args) {
    const Result<cli::GlobalOptions> parsed = cli::parseGlobalOptions(args);
    return parsed ? QString() : parsed.error().message;
}

Result<MachineFile> machineWithSlot(const QByteArray& slot) {
    return parseMachineFile(
        "{\"machine\": \"rack\", \"devices\": [{\"name\": \"card\", "
        "\"family\": \"slotted\", \"port\": \"sim\", \"slot\": " +
            slot + "}]}",
        QStringLiteral("rack.json"));
}

// "path:line: literal" for each of `literals` in the code (not the
// comments) of app/, comm/, model/ and ui/ in a file `searched(path, text)`
// accepts (path relative to the source tree).
QStringList literalsIn(
    const QStringList& literals,
    const std::function<bool(const QString& path, const QString& text)>& searched) {
    const QString root = QStringLiteral(CAMBENCH_SOURCE_DIR);
    QStringList found;
    for (const char* layer : {"app", "comm", "model", "ui"}) {
        QDirIterator it(root + u'/' + QLatin1String(layer),
                        {QStringLiteral("*.cpp"), QStringLiteral("*.h")}, QDir::Files,
                        QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = QDir(root).relativeFilePath(it.next());
            QFile file(it.filePath());
            if (!file.open(QIODevice::ReadOnly)) {
                found << path + QStringLiteral(": cannot be read");
                continue;
            }
            const QString text = QString::fromUtf8(file.readAll());
            if (!searched(path, text)) continue;
            const QStringList lines = text.split(u'\n');
            for (int i = 0; i < lines.size(); ++i) {
                const QString code = lines.at(i).section(QStringLiteral("//"), 0, 0);
                for (const QString& literal : literals)
                    if (code.contains(literal))
                        found << QStringLiteral("%1:%2: %3").arg(path).arg(i + 1).arg(literal);
            }
        }
    }
    return found;
}

}  // namespace

class TestProtocolOptions : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() {
        test::useTestSettings();
        // The one registration line the family takes.
        registerFamily(fake::slottedParts());
    }

    void theCommandLineTakesTheOption() {
        for (const QStringList& args :
             {QStringList{"--slot", "3", "detect"}, QStringList{"detect", "--slot=3"}}) {
            const Result<cli::GlobalOptions> parsed = cli::parseGlobalOptions(args);
            QVERIFY2(parsed, qPrintable(parsed ? QString() : parsed.error().message));
            // The option alone names the family and its protocol.
            QCOMPARE(parsed->family, QStringLiteral("slotted"));
            QCOMPARE(parsed->protocol, QStringLiteral("slotted-line"));
            QCOMPARE(parsed->protocolSettings()->toMap().value(QStringLiteral("slot")).toInt(), 3);
        }
        // Not given: its default.
        const Result<cli::GlobalOptions> plain =
            cli::parseGlobalOptions({"--family", "slotted", "detect"});
        QVERIFY(plain);
        QCOMPARE(plain->protocolSettings()->toMap().value(QStringLiteral("slot")).toInt(), 1);
        // --help lists it with its range, as the protocol declares it.
        QVERIFY2(cli::usageText().contains(QLatin1String("[--slot N]")), "usage line");
        QVERIFY2(
            cli::usageText().contains(QLatin1String("the slot of the rack the device sits in")),
            "help line");
    }

    void theCommandLineRefusesItOutOfRange() {
        QCOMPARE(errorOf({"--slot", "9", "detect"}),
                 QStringLiteral("--slot must be a whole number from 1 to 8, not \"9\""));
        QCOMPARE(errorOf({"--slot", "x", "detect"}),
                 QStringLiteral("--slot must be a whole number from 1 to 8, not \"x\""));
        // An option of this family's protocol names the family: with
        // another family asked for, both are named.
        const QString other = errorOf({"--family", "camcon", "--slot", "2", "detect"});
        QVERIFY2(
            other.contains(QLatin1String("--slot 2 is for a protocol of the slotted family")) &&
                other.contains(QLatin1String("--family camcon")),
            qPrintable(other));
        // A protocol that does not take it says so, and which one does.
        QCOMPARE(errorOf({"--slot", "2", "--protocol", "standard", "detect"}).isEmpty(), false);
    }

    void aMachineFileTakesTheOption() {
        const Result<MachineFile> machine = machineWithSlot("3");
        QVERIFY2(machine, qPrintable(machine ? QString() : machine.error().message));
        const Result<MachineConnection> connection = machineConnection(machine->devices.first());
        QVERIFY2(connection, qPrintable(connection ? QString() : connection.error().message));
        QCOMPARE(connection->connection.protocol, QStringLiteral("slotted-line"));
        QCOMPARE(connection->protocol->toMap().value(QStringLiteral("slot")).toInt(), 3);
        // The command line's machine commands read the device as a command line.
        QStringList args = machine->devices.first().arguments();
        args << QStringLiteral("detect");
        const Result<cli::GlobalOptions> parsed = cli::parseGlobalOptions(args);
        QVERIFY2(parsed, qPrintable(parsed ? QString() : parsed.error().message));
        QCOMPARE(parsed->protocolSettings()->toMap().value(QStringLiteral("slot")).toInt(), 3);
        // Written down again (New machine), the slot is kept.
        const MachineDevice written =
            machineDeviceFor(QStringLiteral("card"), connection->connection, *connection->protocol);
        QCOMPARE(written.option(QStringLiteral("slot")), QStringLiteral("3"));
    }

    void aMachineFileOutOfRangeIsRefusedNamingTheDevice() {
        const Result<MachineFile> machine = machineWithSlot("0");
        QVERIFY(machine);
        const Result<MachineConnection> connection = machineConnection(machine->devices.first());
        QVERIFY(!connection);
        QCOMPARE(connection.error().message,
                 QStringLiteral("card: \"slot\" must be a whole number from 1 to 8, not \"0\"."));
    }

    void theConnectionPageOffersTheOption() {
        Shell shell;
        shell.start(QStringLiteral("sim:throttle=0"), QStringLiteral("standard"));
        ConnectionPage* page = shell.window()->connectionPage();
        page->setFamily(QStringLiteral("slotted"));
        page->setProtocol(QStringLiteral("slotted-line"));
        auto* slot = page->findChild<QSpinBox*>(QStringLiteral("option-slot"));
        QVERIFY(slot);
        QCOMPARE(slot->minimum(), 1);
        QCOMPARE(slot->maximum(), 8);
        QCOMPARE(slot->value(), 1);
        QVERIFY(slot->toolTip().startsWith(QLatin1String("The slot of the rack")));
        bool labelled = false;
        for (QLabel* label : page->findChildren<QLabel*>())
            labelled =
                labelled || (label->text() == QLatin1String("Slot:") && label->buddy() == slot);
        QVERIFY(labelled);
        slot->setValue(6);
        QCOMPARE(page->protocolSettings()->toMap().value(QStringLiteral("slot")).toInt(), 6);
    }

    // grep finds no option or protocol id of a family in the shell: the
    // files outside the family folders (camcon/, mc1/, compax3/) and
    // app/registry's family folders spell none of the registered
    // protocols' ids, option words (--pc-number) or settings keys (pcNumber)
    // in a string literal.
    void theShellNamesNoOptionOrProtocol() {
        QStringList literals;
        for (const comm::ProtocolInfo* protocol : comm::ProtocolRegistry::instance().all()) {
            if (protocol->familyId == QLatin1String("slotted")) continue;
            // A protocol named as its family is named ("mc1"), the family
            // registry's business: only ids of their own are counted.
            if (protocol->id != protocol->familyId)
                literals << QLatin1Char('"') + protocol->id + u'"';
            for (const comm::ProtocolOption& option : protocol->options) {
                for (const QString& name : QStringList{option.name} + option.aliases)
                    literals << QStringLiteral("\"--%1\"").arg(name);
                literals << QLatin1Char('"') + option.settingsKey + u'"';
            }
        }
        literals.removeDuplicates();
        // "device" is also the shell's own word (a device's name in a
        // backup's manifest, the identity's "device" line).
        literals.removeAll(QStringLiteral("\"device\""));
        const QRegularExpression familyFolder(QStringLiteral("(^|/)(camcon|mc1|compax3)/"));
        const QStringList found = literalsIn(literals, [&](const QString& path, const QString&) {
            return !familyFolder.match(path).hasMatch();
        });
        QVERIFY2(found.isEmpty(), qPrintable(found.join(u'\n')));
    }

    // Issue 38, item 2: a built-in family's id is one constant
    // (model/xy/xy_family_id.h), spelled as a string nowhere else. Where a
    // protocol has its family's name ("mc1", "compax3"), the family's own
    // folders spell that protocol id.
    void eachFamilyIdIsSpelledOnce() {
        QStringList found;
        for (const QString& id :
             {QStringLiteral("camcon"), QStringLiteral("mc1"), QStringLiteral("compax3")}) {
            QVERIFY(comm::FamilyRegistry::instance().find(id));
            const bool alsoAProtocol = comm::ProtocolRegistry::instance().find(id) != nullptr;
            const QString constant = QStringLiteral("model/%1/%1_family_id.h").arg(id);
            const QRegularExpression ownFolder(QStringLiteral("(^|/)%1/").arg(id));
            found << literalsIn({u'"' + id + u'"'}, [&](const QString& path, const QString&) {
                if (path == constant) return false;
                return !(alsoAProtocol && ownFolder.match(path).hasMatch());
            });
        }
        QVERIFY2(found.isEmpty(), qPrintable(found.join(u'\n')));
    }
};

QTEST_MAIN(TestProtocolOptions)
#include "tst_protocol_options.moc"
