// Issue 15: Compax3Drive (the Compax3 device) against the simulated drive
// through the real request engine: identity, objects read and written in
// every form, refusals with their number, RS485 addressing with and without
// the '*', the motion sequence, a bus scan, 1 % damaged and lost answers
// (right results; a lost answer to a start never sent again), and the
// parameter set round trip (backup → change → verify differs → restore →
// verify equal).
#include "comm/compax3/compax3_drive.h"
#include "comm/compax3/usecases/compax3_parameters.h"
#include "comm/sim/compax3/sim_compax3_line.h"
#include "comm/sim/sim_transport.h"

#include <QTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

// A simulated drive (RS232, or RS485 at `simAddress`) behind a Compax3Drive
// that addresses `address` (-1: RS232).
struct Bench {
    explicit Bench(int simAddress = -1, int address = -1, const SimFaultSettings& faults = {},
                   const QString& type = QStringLiteral("S025V2"))
        : transport(std::make_unique<SimCompax3Line>(simAddress, SimCompax3Drive(type), faults),
                    SimPacer(115200, false, 10), QStringLiteral("simulated Compax3")),
          drive(transport,
                address < 0 ? QStringLiteral("compax3") : QStringLiteral("compax3-rs485"), address,
                0, timing()) {
        (void)transport.open();
    }
    static LineTiming timing() {
        LineTiming t;
        t.baud = 115200;
        return t;
    }
    SimCompax3Drive& sim() { return static_cast<SimCompax3Line&>(transport.line()).drive(); }

    SimTransport transport;
    Compax3Drive drive;
    Compax3Device& device = drive;
};

// Waits (bounded) until the axis stands; its status then.
Compax3DriveStatus waitStill(Compax3Device& device) {
    Result<Compax3DriveStatus> status = device.status();
    for (int i = 0; i < 300 && status && status->moving(); ++i) {
        QTest::qWait(10);
        status = device.status();
    }
    return status ? *status : Compax3DriveStatus{};
}

}  // namespace

class TestCompax3Drive : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void identifiesTheDrive() {
        Bench bench;
        const Result<Compax3Identity> identity = bench.device.identity();
        QVERIFY2(identity.ok(), qPrintable(identity.error().message));
        QVERIFY(identity->info.startsWith(QLatin1String("Compax3 S025V2")));
        QCOMPARE(identity->serial, QStringLiteral("C3-4711-0815"));
        QCOMPARE(identity->type(), QStringLiteral("S025V2"));
        QVERIFY(bench.device.identify()->contains(QLatin1String("serial number C3-4711-0815")));
    }

    void readsAndWritesObjects() {
        Bench bench;
        QCOMPARE(*bench.device.readObject(compax3SetTarget(2), false), QStringLiteral("200"));
        QVERIFY(bench.device.writeObject(compax3SetTarget(2), QStringLiteral("12.5")).ok());
        QCOMPARE(bench.sim().value(compax3SetTarget(2)), QStringLiteral("12.5"));
        QVERIFY(bench.device.writeObject(compax3SetMode(2), QStringLiteral("$2")).ok());
        QCOMPARE(*bench.device.readObject(compax3SetMode(2), true), QStringLiteral("$2"));
        QCOMPARE(*bench.device.readObject(kCompax3StatusWord, true), QStringLiteral("$505"));
    }

    void refusalsCarryTheDrivesNumber() {
        Bench bench;
        const Status readOnly = bench.device.writeObject(kCompax3Position, QStringLiteral("1"));
        QCOMPARE(readOnly.error().kind, ErrorKind::DeviceError);
        QVERIFY2(readOnly.error().message.contains(QLatin1String("!0003")),
                 qPrintable(readOnly.error().message));
        const Status range = bench.device.writeObject(compax3SetMode(1), QStringLiteral("7"));
        QVERIFY(range.error().message.contains(QLatin1String("!0004")));
        const Result<QString> unknown = bench.device.readObject({4321, 1}, false);
        QCOMPARE(unknown.error().deviceCode, 2);
        QVERIFY(unknown.error().message.contains(QLatin1String("no such object")));
        // The drive's own syntax check: a comma where the point belongs.
        const Status comma = bench.device.writeObject(compax3SetTarget(1), QStringLiteral("12,5"));
        QVERIFY(comma.error().message.contains(QLatin1String("!0001")));
        QCOMPARE(bench.sim().value(compax3SetTarget(1)), QStringLiteral("100"));
    }

    void rs485AddressesOneDriveAndAcceptsTheMark() {
        Bench bench(7, 7);
        QCOMPARE(*bench.device.readObject(compax3SetTarget(3), false), QStringLiteral("300"));
        QVERIFY(bench.device.identify()->contains(QLatin1String("address 7")));
        Bench other(7, 8);
        const Result<QString> silent = other.device.readObject(compax3SetTarget(3), false);
        QCOMPARE(silent.error().kind, ErrorKind::Communication);
        QVERIFY2(silent.error().message.contains(QLatin1String("address 8")),
                 qPrintable(silent.error().message));
    }

    void aBusScanFindsTheDrive() {
        Bench bench(42, 0);
        QList<qint64> seen;
        const Result<QList<int>> found =
            bench.device.scanBus(0, 99, [&seen](qint64 done, qint64) { seen << done; });
        QVERIFY2(found.ok(), qPrintable(found.error().message));
        QCOMPARE(*found, QList<int>{42});
        QCOMPARE(seen.size(), 100);
        // The drive's own address is kept for what follows.
        QCOMPARE(bench.drive.engine().backend().describe(),
                 QStringLiteral("the Compax3 at address 0 (RS485)"));
    }

    void theMotionSequenceMovesTheAxis() {
        Bench bench;
        Compax3SetMove move;
        move.set = 1;
        move.target = 40;
        move.velocity = 2000;
        // Powerless: refused before anything moves.
        const Result<Compax3DriveStatus> refused = bench.device.moveSet(move);
        QVERIFY(!refused.ok());
        QVERIFY(refused.error().message.contains(QLatin1String("enable it first")));
        bench.sim().raiseError(0x7320);
        const Result<Compax3DriveStatus> enabled = bench.device.motion(Compax3Motion::Enable);
        QVERIFY2(enabled.ok(), qPrintable(enabled.error().message));
        QCOMPARE(enabled->lastError, 1);  // the rising edge acknowledged it
        QVERIFY(!enabled->status.powerless());
        const Result<Compax3DriveStatus> started = bench.device.moveSet(move);
        QVERIFY2(started.ok(), qPrintable(started.error().message));
        QCOMPARE(started->controlWord, compax3control::start(1));
        QCOMPARE(bench.sim().value(compax3SetTarget(1)), QStringLiteral("40"));
        const Compax3DriveStatus still = waitStill(bench.device);
        QCOMPARE(still.position, 40.0);
        QCOMPARE(still.lastSet, 1);
        QVERIFY(still.status.positionReached());

        QVERIFY(bench.device.motion(Compax3Motion::JogMinus).ok());
        QTest::qWait(50);
        QVERIFY(bench.sim().moving());
        const Result<Compax3DriveStatus> stopped = bench.device.motion(Compax3Motion::Stop);
        QVERIFY(stopped.ok());
        QVERIFY(!bench.sim().moving());
        QVERIFY(stopped->position < 40.0);
        QVERIFY(bench.device.motion(Compax3Motion::Disable)->status.powerless());
        // A set value out of range is refused before the first byte.
        move.velocity = -5;
        QVERIFY(bench.device.moveSet(move).error().message.contains(QLatin1String("range")));
    }

    void aLostAnswerToAStartIsNeverSentAgain() {
        SimFaultSettings faults;
        faults.dropFirstReplyTo = "O1100,3=$6103";  // start set 1
        Bench bench(-1, -1, faults);
        QVERIFY(bench.device.motion(Compax3Motion::Enable).ok());
        Compax3SetMove move;
        move.set = 1;
        move.target = 30;
        move.velocity = 1000;
        const Result<Compax3DriveStatus> started = bench.device.moveSet(move);
        QVERIFY(!started.ok());
        QCOMPARE(started.error().kind, ErrorKind::Communication);
        const QString message = started.error().message;
        QVERIFY2(message.contains(QLatin1String("was not sent again")), qPrintable(message));
        QVERIFY2(message.contains(QLatin1String("the command was taken")), qPrintable(message));
        QCOMPARE(bench.drive.engine().lastAttempts(), 1);
        // It moved once, to 30: not twice (a relative set would show it).
        QCOMPARE(waitStill(bench.device).position, 30.0);
    }

    void onePercentDamagedAndLostAnswersStillGiveTheRightValues() {
        SimFaultSettings faults;
        faults.corruptProbability = 0.01;
        faults.dropProbability = 0.01;
        faults.seed = 15;
        Bench bench(-1, -1, faults);
        int ok = 0;
        for (int round = 0; round < 3; ++round)
            for (int set = 0; set <= 31; ++set) {
                const Result<QString> value = bench.device.readObject(compax3SetTarget(set), false);
                if (!value) continue;  // a failure is said; a wrong value never passes
                QCOMPARE(*value, compax3NumberText(set * 100.0));
                ++ok;
            }
        QVERIFY2(ok >= 90, qPrintable(QString::number(ok)));
    }

    void aBackupOverADamagingLineHoldsTheDrivesValues() {
        // No checksum: a damaged digit reads as another number. The backup
        // reads each object until two answers agree; 10 % damaged and 5 %
        // lost answers must still give exactly the drive's values.
        using namespace cambench::usecases;
        SimFaultSettings faults;
        faults.corruptProbability = 0.10;
        faults.dropProbability = 0.05;
        faults.seed = 1501;
        Bench bench(-1, -1, faults);
        QList<Compax3ObjectId> objects;
        for (int set = 0; set <= 31; ++set)
            objects << compax3SetTarget(set) << compax3SetVelocity(set);
        for (int set = 0; set <= 31; ++set)
            bench.sim().setValue(compax3SetTarget(set), compax3NumberText(set * 1111.25 - 7000));
        const Result<Compax3Backup> backup = takeCompax3Parameters(bench.device, objects);
        QVERIFY2(backup.ok(), qPrintable(backup.error().message));
        QCOMPARE(backup->set.values.size(), objects.size());
        for (const Compax3ParameterValue& value : backup->set.values)
            QCOMPARE(value.value, bench.sim().value(value.id));
    }

    void aParameterSetRoundTrips() {
        using namespace cambench::usecases;
        Bench bench;
        const QList<Compax3ObjectId> objects = Compax3Dictionary::builtin().parameters();
        const Result<Compax3Backup> backup = takeCompax3Parameters(bench.device, objects);
        QVERIFY2(backup.ok(), qPrintable(backup.error().message));
        QCOMPARE(backup->set.values.size(), objects.size());
        QVERIFY(backup->refused.isEmpty());

        bench.sim().setValue(compax3SetTarget(5), QStringLiteral("123.25"));
        bench.sim().setValue(compax3SetVelocity(7), QStringLiteral("9"));
        const Result<Compax3Comparison> differs =
            compareCompax3Parameters(bench.device, backup->set);
        QCOMPARE(differs->differences.size(), 2);
        QCOMPARE(
            Compax3Comparison::lineFor(differs->differences.first(), Compax3Dictionary::builtin()),
            QStringLiteral("1901.5 (Set 5 target): file 500, drive 123.25"));

        Compax3RestoreOptions options;
        options.store = true;
        const Result<OutcomeTally> restored = restoreCompax3Parameters(
            bench.device, backup->set, Compax3Dictionary::builtin(), options);
        QVERIFY2(restored.ok(), qPrintable(restored.error().message));
        QVERIFY(restored->complete());
        QCOMPARE(restored->count(WriteState::Written), 3);  // two objects and the store
        QCOMPARE(restored->count(WriteState::Unchanged), objects.size() - 2);
        QVERIFY(restored->lines().last().text.contains(QLatin1String("1904.1 = $32")));
        QVERIFY(compareCompax3Parameters(bench.device, backup->set)->differences.isEmpty());
    }

    void aSetOfAnotherTypeIsRefusedUnlessForced() {
        using namespace cambench::usecases;
        Bench bench(-1, -1, {}, QStringLiteral("S150V4"));
        Compax3ParameterSet set;
        set.drive.info = QStringLiteral("Compax3 S025V2 F10 I10 T40 V04.02");
        set.values = {{compax3SetTarget(1), QStringLiteral("77")}};
        const Result<OutcomeTally> refused =
            restoreCompax3Parameters(bench.device, set, Compax3Dictionary::builtin(), {});
        QVERIFY(!refused.ok());
        QVERIFY(refused.error().message.contains(QLatin1String("nothing was written")));
        QCOMPARE(bench.sim().value(compax3SetTarget(1)), QStringLiteral("100"));
        Compax3RestoreOptions forced;
        forced.force = true;
        QVERIFY(restoreCompax3Parameters(bench.device, set, Compax3Dictionary::builtin(), forced)
                    ->complete());
        QCOMPARE(bench.sim().value(compax3SetTarget(1)), QStringLiteral("77"));
        // A value the dictionary refuses: nothing written, the object named.
        set.values = {{compax3SetTarget(2), QStringLiteral("5")},
                      {compax3SetMode(1), QStringLiteral("9")}};
        const Result<OutcomeTally> badValue =
            restoreCompax3Parameters(bench.device, set, Compax3Dictionary::builtin(), forced);
        QVERIFY(badValue.error().message.contains(QLatin1String("1905.1")));
        QCOMPARE(bench.sim().value(compax3SetTarget(2)), QStringLiteral("200"));
    }
};

QTEST_GUILESS_MAIN(TestCompax3Drive)
#include "tst_compax3_drive.moc"
