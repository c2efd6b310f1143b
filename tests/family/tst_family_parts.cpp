// Issue 31, item 1: the startup check every program runs after registering
// the families (missingFamilyParts, family_parts.h) names each family that
// lacks a part the program must have, and the part. This test links the
// registrations without GUI and CLI parts (cambench_registry), as
// cambench-sim does.
#include "app/registry/family_parts.h"
#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"

#include <QTest>

using namespace cambench;

namespace {

// The lines of `missing` that name family `id`.
QStringList linesOf(const QStringList& missing, const QString& id) {
    return missing.filter(QStringLiteral("family \"%1\"").arg(id));
}

// A family this build could talk to, whose protocol is "<id>-line".
comm::FamilyInfo builtFamily(const QString& id, const QString& title) {
    comm::FamilyInfo family = comm::FamilyInfo::announced(id, title, id + QStringLiteral("-line"));
    family.built = true;
    return family;
}

}  // namespace

class TestFamilyParts : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theBuiltInFamiliesAreRegisteredThroughTheirParts() {
        QStringList ids;
        for (const FamilyParts& parts : registeredFamilies()) ids << parts.id;
        QCOMPARE(ids, (QStringList{QStringLiteral("camcon"), QStringLiteral("mc1"),
                                   QStringLiteral("compax3")}));
        QCOMPARE(comm::FamilyRegistry::instance().defaultId(), QStringLiteral("camcon"));
    }

    void theSimulatorHasEveryPartItNeeds() {
        QCOMPARE(missingFamilyParts(Program::Simulator), QStringList());
        QVERIFY(familiesComplete(Program::Simulator, "tst_family_parts"));
    }

    // Here the GUI's and the CLI's parts are not linked: as the GUI and
    // the CLI, the check names each family and the part it lacks.
    void aProgramWithoutAFamilysPartIsToldWhichAndWhat() {
        const QStringList gui = missingFamilyParts(Program::Gui);
        const QStringList cli = missingFamilyParts(Program::Cli);
        for (const QString& id :
             {QStringLiteral("camcon"), QStringLiteral("mc1"), QStringLiteral("compax3")}) {
            QCOMPARE(linesOf(gui, id).size(), 1);
            QVERIFY2(linesOf(gui, id).first().contains(QLatin1String("no GUI part")),
                     qPrintable(gui.join(QLatin1Char('\n'))));
            QCOMPARE(linesOf(cli, id).size(), 1);
            QVERIFY2(linesOf(cli, id).first().contains(QLatin1String("no command group")),
                     qPrintable(cli.join(QLatin1Char('\n'))));
        }
        QVERIFY(!familiesComplete(Program::Cli, "tst_family_parts"));
    }

    void aFamilyWithoutSimulatorOrChecksIsNamed() {
        FamilyParts half;
        half.id = QStringLiteral("half");
        half.family = [] {
            return builtFamily(QStringLiteral("half"), QStringLiteral("Half Device"));
        };
        half.protocols = [] {
            comm::ProtocolInfo protocol;
            protocol.id = QStringLiteral("half-line");
            protocol.title = QStringLiteral("Half line");
            return QList{protocol};
        };
        registerFamily(half);
        registerFamily(half);  // again: left as it is
        QCOMPARE(registeredFamilies().size(), 4);

        QCOMPARE(linesOf(missingFamilyParts(Program::Simulator), QStringLiteral("half")),
                 QStringList{QStringLiteral(
                     "family \"half\" (Half Device) has no simulator (FamilyParts::simulator)")});
        const QStringList cli = linesOf(missingFamilyParts(Program::Cli), QStringLiteral("half"));
        QCOMPARE(cli.size(), 3);
        QVERIFY(cli.filter(QLatin1String("has no checks")).size() == 1);
        QVERIFY(cli.filter(QLatin1String("has no command group in cambench-cli")).size() == 1);
    }

    void aFamilyRegisteredAroundItsPartsIsNamed() {
        comm::FamilyRegistry::instance().add(
            builtFamily(QStringLiteral("stray"), QStringLiteral("Stray Drive")));
        const QStringList lines =
            linesOf(missingFamilyParts(Program::Simulator), QStringLiteral("stray"));
        QCOMPARE(lines.size(), 1);
        QVERIFY2(lines.first().contains(QLatin1String("not through its FamilyParts")),
                 qPrintable(lines.first()));
    }

    // A family known by name but not built (FamilyInfo::announced) is not
    // asked for parts.
    void anAnnouncedFamilyNeedsNoParts() {
        comm::FamilyRegistry::instance().add(
            comm::FamilyInfo::announced(QStringLiteral("coming"), QStringLiteral("Coming Drive"),
                                        QStringLiteral("coming-line")));
        QVERIFY(linesOf(missingFamilyParts(Program::Gui), QStringLiteral("coming")).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestFamilyParts)
#include "tst_family_parts.moc"
