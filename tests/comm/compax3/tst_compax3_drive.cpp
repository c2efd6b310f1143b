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

#include "../engine/scripted_line.h"

#include <QTest>

#include <functional>

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

// A Compax3Drive on a scripted line and a virtual clock: the bytes it
// writes, compared with telegrams written by hand from the manual's syntax.
// `answer` gives the drive's answer line to each written line (null: none).
struct ScriptedDrive {
    using Answer = std::function<QByteArray(const QByteArray& written, int index)>;
    explicit ScriptedDrive(Answer answer, int address = -1)
        : line(clock,
               [answer](const QByteArray& written, int index) -> QList<test::ScriptedReply> {
                   const QByteArray reply = answer(written, index);
                   if (reply.isNull()) return {};
                   return {{2, reply}};
               }),
          drive(line, address < 0 ? QStringLiteral("compax3") : QStringLiteral("compax3-rs485"),
                address, 0, Bench::timing()) {
        drive.engine().setClock([this] { return clock.nowMs; });
    }
    QList<QByteArray> written() const {
        QList<QByteArray> out;
        for (const test::ScriptedLine::Write& write : line.writes()) out << write.bytes;
        return out;
    }
    test::VirtualClock clock;
    test::ScriptedLine line;
    Compax3Drive drive;
};

// A drive whose status word is `word` and last error `error`: answers its
// reads as the manual says a number is answered (its text and CR), and
// every write with ">" CR. RS485 answers start with '*'.
ScriptedDrive::Answer driveWith(quint16 word, int error, bool rs485 = false) {
    return [word, error, rs485](const QByteArray& written, int) -> QByteArray {
        const QByteArray mark = rs485 ? "*" : "";
        if (written.contains('=')) return mark + ">\r";
        if (written.endsWith("O1000,3\r")) return mark + QByteArray::number(word) + '\r';
        if (written.endsWith("O550,1\r")) return mark + QByteArray::number(error) + '\r';
        if (written.endsWith("O680,5\r")) return mark + "12.5\r";
        if (written.endsWith("O1000,4\r")) return mark + "1\r";
        if (written.endsWith("O1100,3\r")) return mark + "1\r";
        return {};
    };
}

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
        const Result<Compax3CommandResult> refused = bench.device.moveSet(move);
        QVERIFY(!refused.ok());
        QVERIFY(refused.error().message.contains(QLatin1String("enable it first")));
        bench.sim().raiseError(0x7320);
        const Result<Compax3CommandResult> enabled = bench.device.motion(Compax3Motion::Enable);
        QVERIFY2(enabled.ok(), qPrintable(enabled.error().message));
        QCOMPARE(enabled->after->lastError, 1);  // the rising edge acknowledged it
        QVERIFY(!enabled->after->status.powerless());
        const Result<Compax3CommandResult> started = bench.device.moveSet(move);
        QVERIFY2(started.ok(), qPrintable(started.error().message));
        QCOMPARE(started->after->controlWord, compax3control::start(1));
        QCOMPARE(bench.sim().value(compax3SetTarget(1)), QStringLiteral("40"));
        const Compax3DriveStatus still = waitStill(bench.device);
        QCOMPARE(still.position, 40.0);
        QCOMPARE(still.lastSet, 1);
        QVERIFY(still.status.positionReached());

        QVERIFY(bench.device.motion(Compax3Motion::JogMinus).ok());
        QTest::qWait(50);
        QVERIFY(bench.sim().moving());
        const Result<Compax3CommandResult> stopped = bench.device.motion(Compax3Motion::Stop);
        QVERIFY(stopped.ok());
        QVERIFY(!bench.sim().moving());
        QVERIFY(stopped->after->position < 40.0);
        QVERIFY(bench.device.motion(Compax3Motion::Disable)->after->status.powerless());
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
        const Result<Compax3CommandResult> started = bench.device.moveSet(move);
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
        const Result<Compax3Backup> backup =
            takeCompax3Parameters(bench.device, objects, Compax3Dictionary::builtin());
        QVERIFY2(backup.ok(), qPrintable(backup.error().message));
        QCOMPARE(backup->set.values.size(), objects.size());
        for (const Compax3ParameterValue& value : backup->set.values)
            QCOMPARE(value.value, bench.sim().value(value.id));
    }

    void aParameterSetRoundTrips() {
        using namespace cambench::usecases;
        Bench bench;
        const QList<Compax3ObjectId> objects = Compax3Dictionary::builtin().parameters();
        const Result<Compax3Backup> backup =
            takeCompax3Parameters(bench.device, objects, Compax3Dictionary::builtin());
        QVERIFY2(backup.ok(), qPrintable(backup.error().message));
        QCOMPARE(backup->set.values.size(), objects.size());
        QVERIFY(backup->refused.isEmpty());

        bench.sim().setValue(compax3SetTarget(5), QStringLiteral("123.25"));
        bench.sim().setValue(compax3SetVelocity(7), QStringLiteral("9"));
        const Result<Compax3Comparison> differs =
            compareCompax3Parameters(bench.device, backup->set, Compax3Dictionary::builtin());
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
        // Two objects, then the two sets they are in stored (1904.n = $32).
        QCOMPARE(restored->count(WriteState::Written), 2 + 2);
        QCOMPARE(restored->count(WriteState::Unchanged), objects.size() - 2);
        QVERIFY2(restored->lines().last().text.contains(QLatin1String("1904.7 = $32")),
                 qPrintable(restored->lines().last().text));
        QVERIFY(bench.sim().requests().contains("O1904,5=$32"));
        QVERIFY(!bench.sim().requests().contains("O1904,6=$32"));
        QVERIFY(compareCompax3Parameters(bench.device, backup->set, Compax3Dictionary::builtin())
                    ->differences.isEmpty());
    }

    void aSetOfAnotherTypeIsRefusedUnlessForced() {
        using namespace cambench::usecases;
        Bench bench(-1, -1, {}, QStringLiteral("S150V4"));
        Compax3ParameterSet set;
        set.drive.info = QStringLiteral("Compax3 S025V2 F10 I10 T40 V04.02");
        set.drive.serial = QStringLiteral("C3-0001");
        set.values = {{compax3SetTarget(1), QStringLiteral("77")}};
        const Result<OutcomeTally> refused =
            restoreCompax3Parameters(bench.device, set, Compax3Dictionary::builtin(), {});
        QVERIFY(!refused.ok());
        QVERIFY2(refused.error().message.contains(QLatin1String("Nothing was written")),
                 qPrintable(refused.error().message));
        QCOMPARE(bench.sim().value(compax3SetTarget(1)), QStringLiteral("100"));
        // The replacement accepted, another type still needs --force.
        Compax3RestoreOptions forced;
        forced.replacement = ReplacementConsent::any();
        const Result<OutcomeTally> otherType =
            restoreCompax3Parameters(bench.device, set, Compax3Dictionary::builtin(), forced);
        QVERIFY(!otherType.ok());
        QVERIFY2(otherType.error().message.contains(QLatin1String("of type S025V2")),
                 qPrintable(otherType.error().message));
        QCOMPARE(bench.sim().value(compax3SetTarget(1)), QStringLiteral("100"));
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

    // Issue 35, item 8: a set goes only to the drive it was read from (its
    // serial number, 1.4, and type): another drive of the same type is
    // refused naming both, with no write on the line, until accepted.
    void aSetOfAnotherDriveIsRefusedUntilAcceptedAsItsReplacement() {
        using namespace cambench::usecases;
        Bench bench;
        const Result<Compax3Identity> drive = bench.device.identity();
        QVERIFY(drive.ok());
        Compax3ParameterSet set;
        set.drive = *drive;
        set.drive.serial = QStringLiteral("C3-0001");
        set.values = {{compax3SetTarget(1), QStringLiteral("77")}};
        const qsizetype before = bench.sim().requests().size();
        const Result<OutcomeTally> refused =
            restoreCompax3Parameters(bench.device, set, Compax3Dictionary::builtin(), {});
        QVERIFY(!refused.ok());
        QCOMPARE(refused.error().kind, ErrorKind::InvalidData);
        QVERIFY2(refused.error().message.contains(
                     QStringLiteral("another device answers: expected serial C3-0001, found "
                                    "serial %1")
                         .arg(drive->serial)),
                 qPrintable(refused.error().message));
        for (const QByteArray& request : bench.sim().requests().mid(before))
            QVERIFY2(!request.contains('='), request.constData());  // reads only
        QCOMPARE(bench.sim().value(compax3SetTarget(1)), QStringLiteral("100"));
        Compax3RestoreOptions accepted;
        accepted.replacement = ReplacementConsent::of(drive->deviceIdentity());
        QVERIFY(restoreCompax3Parameters(bench.device, set, Compax3Dictionary::builtin(), accepted)
                    ->complete());
        QCOMPARE(bench.sim().value(compax3SetTarget(1)), QStringLiteral("77"));
    }

    // Issue 27: each acting request's bytes as the manual writes a command
    // (`O index,subindex=value`, `$` for hexadecimal; the control word's
    // bits as docs/protocols/compax3.md reads them), counted at the drive.
    void actingRequestsAreTheManualsBytes() {
        Bench bench;
        const qsizetype start = bench.sim().requests().size();
        QVERIFY(bench.device.motion(Compax3Motion::Enable).ok());
        QList<QByteArray> sent = bench.sim().requests().mid(start);
        QList<QByteArray> writes;
        for (const QByteArray& request : sent)
            if (request.contains('=')) writes << request;
        // Powerless first: off, then on (the rising edge acknowledges).
        QCOMPARE(writes, (QList<QByteArray>{"O1100,3=$0000", "O1100,3=$0001"}));
        QCOMPARE(sent.first(), QByteArray("O1000,3"));  // the status read first

        auto writesOf = [&bench](const std::function<void()>& act) {
            const qsizetype from = bench.sim().requests().size();
            act();
            QList<QByteArray> out;
            for (const QByteArray& request : bench.sim().requests().mid(from))
                if (request.contains('=')) out << request;
            return out;
        };
        QCOMPARE(writesOf([&] { QVERIFY(bench.device.motion(Compax3Motion::JogPlus).ok()); }),
                 QList<QByteArray>{"O1100,3=$4007"});
        QCOMPARE(writesOf([&] { QVERIFY(bench.device.motion(Compax3Motion::JogMinus).ok()); }),
                 QList<QByteArray>{"O1100,3=$400B"});
        QCOMPARE(writesOf([&] { QVERIFY(bench.device.motion(Compax3Motion::Stop).ok()); }),
                 QList<QByteArray>{"O1100,3=$0001"});
        // A set start writes only what differs from the drive (set 3's
        // target is 300 already), selects the set, then its start edge.
        Compax3SetMove move;
        move.set = 3;
        move.target = 300;
        move.velocity = 5000;
        QCOMPARE(writesOf([&] { QVERIFY(bench.device.moveSet(move).ok()); }),
                 (QList<QByteArray>{"O1902,3=5000", "O1100,3=$4303", "O1100,3=$6303"}));
        // The line itself: the request and CR, on RS485 the address first.
        QCOMPARE(compax3RequestLine("O1100,3=$0001", -1), QByteArray("O1100,3=$0001\r"));
        QCOMPARE(compax3RequestLine("O1100,3=$0001", 7), QByteArray("7O1100,3=$0001\r"));
    }

    void enableNeverDropsPowerOnAPoweredDrive() {
        Bench bench;
        QVERIFY(bench.device.motion(Compax3Motion::Enable).ok());
        QVERIFY(bench.device.motion(Compax3Motion::JogPlus).ok());
        const qsizetype from = bench.sim().requests().size();
        const Result<Compax3CommandResult> again = bench.device.motion(Compax3Motion::Enable);
        QVERIFY2(again.ok(), qPrintable(again.error().message));
        QVERIFY2(again->note.contains(QLatin1String("nothing was sent")), qPrintable(again->note));
        for (const QByteArray& request : bench.sim().requests().mid(from))
            QVERIFY2(!request.contains('='), request.constData());
        QVERIFY(bench.sim().moving());  // the jog runs on: Enable did not touch it
        QVERIFY(bench.device.motion(Compax3Motion::Stop).ok());
    }

    void anAcknowledgedCommandStaysDoneWhenItsReadBackIsRefused() {
        Bench bench;
        for (const Compax3ObjectId& id : {kCompax3StatusWord, kCompax3LastError, kCompax3Position,
                                          kCompax3LastSet, kCompax3ControlWord})
            bench.sim().refuseReads(id);
        const Result<Compax3CommandResult> jog = bench.device.motion(Compax3Motion::JogPlus);
        QVERIFY2(jog.ok(), qPrintable(jog.error().message));
        QVERIFY(!jog->after);
        QVERIFY2(jog->readBackFailed.contains(QLatin1String("!0005")),
                 qPrintable(jog->readBackFailed));
        QVERIFY(bench.sim().moving());
        // STOP through the shell's seam: acknowledged, though its read-back fails.
        MotionControl* control = bench.drive.motionControl();
        QVERIFY(control);
        const MotionStopReport report = control->stopAllMotion();
        QVERIFY(report.allAcknowledged());
        QVERIFY2(report.lines.first().detail.contains(QLatin1String("could not be read back")),
                 qPrintable(report.lines.first().detail));
        // Issue 35 item 2: with the status unreadable, the STOP cannot know
        // whether b0 is 1, so it stops with the word that cannot power the
        // drive, and says so.
        QVERIFY2(report.lines.first().detail.contains(QLatin1String("switching its power off")),
                 qPrintable(report.lines.first().detail));
        QVERIFY(!bench.sim().moving());
        QVERIFY(!bench.sim().powered());
        QVERIFY(!control->activeMotion().ok());  // cannot tell: an error, not "nothing"
    }

    void theShellsStopAndActiveMotion() {
        SimFaultSettings faults;
        faults.dropFirstReplyTo = "O1100,3=$0001";  // the first STOP's answer is lost
        Bench bench(4, 4, faults);
        MotionControl* control = bench.drive.motionControl();
        QVERIFY(control);
        // Issue 35 item 7: "powerless" read through the provisional status
        // word is no fact: it cannot tell.
        const Result<QStringList> still = control->activeMotion();
        QVERIFY(!still.ok());
        QVERIFY2(still.error().message.contains(QLatin1String("provisional")),
                 qPrintable(still.error().message));
        QVERIFY(bench.device.motion(Compax3Motion::JogPlus).ok());
        const Result<QStringList> active = control->activeMotion();
        QCOMPARE(active->size(), 1);
        QVERIFY2(active->first().contains(QLatin1String("address 4")) &&
                     active->first().contains(QLatin1String("moves")),
                 qPrintable(active->first()));
        const qsizetype from = bench.sim().requests().size();
        const MotionStopReport report = control->stopAllMotion();
        QVERIFY(report.allAcknowledged());
        QCOMPARE(report.lines.first().what, QStringLiteral("Compax3 drive at address 4"));
        // Repeated after the lost answer: twice at the drive, stopped.
        QCOMPARE(bench.sim().requests().mid(from).count("O1100,3=$0001"), 2);
        QVERIFY(!bench.sim().moving());
        QCOMPARE(*control->activeMotion(),
                 QStringList{QStringLiteral("Compax3 drive at address 4: the axis is powered (as "
                                            "read through provisional object numbers)")});
    }

    // Issue 35 item 2: STOP changes nothing but motion. The telegrams are
    // the manual's syntax written out by hand: a read is "O index,subindex"
    // CR, a write "O index,subindex=value" CR with "$" before a hexadecimal
    // value, RS485 puts the address first and answers with '*'. Status
    // words (reading C2): $0105 moving (no error, I0, I2), $0505 powerless,
    // $0405 powerless with an error.
    void stopTelegramsAreTheManualsBytes() {
        // Powered and moving: the status read, then $0001 (b0 held at 1,
        // the stop bits cleared), then the state read back.
        ScriptedDrive moving(driveWith(0x0105, 1));
        const Result<Compax3CommandResult> stopped = moving.drive.motion(Compax3Motion::Stop);
        QVERIFY2(stopped.ok(), qPrintable(stopped.error().message));
        QCOMPARE(moving.written().mid(0, 2), (QList<QByteArray>{"O1000,3\r", "O1100,3=$0001\r"}));
        QCOMPARE(moving.written().mid(2), (QList<QByteArray>{"O1000,3\r", "O550,1\r", "O680,5\r",
                                                             "O1000,4\r", "O1100,3\r"}));
        QVERIFY(!stopped->nothingSent);

        // Powerless: the status read, then only reads; nothing written.
        ScriptedDrive powerless(driveWith(0x0505, 1));
        const Result<Compax3CommandResult> nothing = powerless.drive.motion(Compax3Motion::Stop);
        QVERIFY2(nothing.ok(), qPrintable(nothing.error().message));
        QVERIFY(nothing->nothingSent);
        QCOMPARE(nothing->note, QStringLiteral("not powered: nothing to stop (nothing was sent)"));
        QCOMPARE(powerless.written().first(), QByteArray("O1000,3\r"));
        for (const QByteArray& written : powerless.written())
            QVERIFY2(!written.contains('='), written.constData());

        // Powerless in following error ($7320): the same; its error is never
        // acknowledged by a STOP. The shell's STOP says "nothing to stop".
        ScriptedDrive inError(driveWith(0x0405, 0x7320), 7);
        const MotionStopReport report = inError.drive.motionControl()->stopAllMotion();
        QVERIFY(report.allAcknowledged());
        QVERIFY(report.lines.first().nothingToStop);
        QCOMPARE(inError.written().first(), QByteArray("7O1000,3\r"));
        for (const QByteArray& written : inError.written())
            QVERIFY2(!written.contains('='), written.constData());

        // RS485, powered: the address in front of each telegram.
        ScriptedDrive rs485(driveWith(0x0105, 1, true), 7);
        QVERIFY(rs485.drive.motion(Compax3Motion::Stop).ok());
        QCOMPARE(rs485.written().mid(0, 2), (QList<QByteArray>{"7O1000,3\r", "7O1100,3=$0001\r"}));
    }

    void aStopWhoseStatusReadFailsCannotPowerTheDrive() {
        // The status word does not come: whether b0 is 1 is unknown, so the
        // one word that can never be its rising edge goes out ($0000), and
        // the result says that power was switched off.
        const ScriptedDrive::Answer powered = driveWith(0x0105, 1);
        ScriptedDrive silent([powered](const QByteArray& written, int index) {
            return index < 2 ? QByteArray() : powered(written, index);
        });
        const Result<Compax3CommandResult> stopped = silent.drive.motion(Compax3Motion::Stop);
        QVERIFY2(stopped.ok(), qPrintable(stopped.error().message));
        QCOMPARE(silent.written().mid(0, 3),
                 (QList<QByteArray>{"O1000,3\r", "O1000,3\r", "O1100,3=$0000\r"}));
        for (const QByteArray& written : silent.written())
            QVERIFY2(!written.contains("=$0001"), written.constData());
        QVERIFY2(stopped->note.contains(QLatin1String("switching its power off (1100.3 = $0000)")),
                 qPrintable(stopped->note));
    }

    // The simulated drive as the control word's reading says a Compax3 acts.
    void theSimulatedDrivesPowerFollowsTheControlWord() {
        SimCompax3Drive drive;
        qint64 now = 0;
        auto ask = [&drive, &now](const char* request) {
            now += 20;
            return drive.answer(QByteArray(request), now);
        };
        // A powerless drive does not move: a jog word without the edge.
        QCOMPARE(ask("O1100,3=$0000"), QByteArray(">"));
        drive.raiseError(0x7320);
        // b0 written again at 0, then the stop bits and jog: no edge of b0.
        QCOMPARE(ask("O1100,3=$4006"), QByteArray(">"));
        QVERIFY(!drive.moving());
        QVERIFY(!drive.powered());
        QCOMPARE(drive.lastError(), 0x7320);
        // The rising edge of b0 powers and acknowledges.
        QCOMPARE(ask("O1100,3=$0001"), QByteArray(">"));
        QVERIFY(drive.powered());
        QCOMPARE(drive.lastError(), 1);
        // An error stops the axis and drops power; it holds until the next
        // rising edge: b0 written at 1 again is none.
        QCOMPARE(ask("O1100,3=$4007"), QByteArray(">"));
        QVERIFY(drive.moving());
        drive.raiseError(0x7320);
        QVERIFY(!drive.moving());
        QVERIFY(!drive.powered());
        QCOMPARE(ask("O1100,3=$0001"), QByteArray(">"));
        QVERIFY(!drive.powered());
        QCOMPARE(drive.lastError(), 0x7320);
        QCOMPARE(ask("O1000,3").toInt() & 0x0500, 0x0400);  // powerless, error
        // A start needs power.
        QCOMPARE(ask("O1100,3=$4103"), QByteArray(">"));
        QCOMPARE(ask("O1100,3=$6103"), QByteArray("!0005"));
        QCOMPARE(ask("O1100,3=$0000"), QByteArray(">"));
        QCOMPARE(ask("O1100,3=$0001"), QByteArray(">"));
        QVERIFY(drive.powered());
        QCOMPARE(drive.lastError(), 1);
    }

    void aStopLeavesAPowerlessDrivePowerless() {
        // Issue 35 item 2, against the simulated drive: disable, then STOP;
        // a drive in following error with its power off, then STOP.
        Bench bench;
        QVERIFY(bench.device.motion(Compax3Motion::Enable).ok());
        QVERIFY(bench.device.motion(Compax3Motion::Disable).ok());
        qsizetype from = bench.sim().requests().size();
        const Result<Compax3CommandResult> stopped = bench.device.motion(Compax3Motion::Stop);
        QVERIFY2(stopped.ok(), qPrintable(stopped.error().message));
        QVERIFY(stopped->nothingSent);
        QVERIFY(!bench.sim().powered());
        for (const QByteArray& request : bench.sim().requests().mid(from))
            QVERIFY2(!request.contains('='), request.constData());

        QVERIFY(bench.device.motion(Compax3Motion::Enable).ok());
        QVERIFY(bench.device.motion(Compax3Motion::JogPlus).ok());
        bench.sim().raiseError(0x7320);
        from = bench.sim().requests().size();
        const MotionStopReport report = bench.drive.motionControl()->stopAllMotion();
        QVERIFY(report.allAcknowledged());
        QVERIFY(report.lines.first().nothingToStop);
        QVERIFY(!bench.sim().powered());
        QCOMPARE(bench.sim().lastError(), 0x7320);
        for (const QByteArray& request : bench.sim().requests().mid(from))
            QVERIFY2(!request.contains('='), request.constData());
        const Compax3DriveStatus after = *bench.device.status();
        QVERIFY(after.status.powerless());
        QVERIFY(!after.status.noError());
        QCOMPARE(after.lastError, 0x7320);
    }

    // Issue 35 item 9: answers 150 ms, 400 ms and 1 s late, past the
    // first-byte time (about 0.1 s): every value is its own request's.
    void lateAnswersAreNeverAnotherRequests_data() {
        QTest::addColumn<int>("delayMs");
        QTest::newRow("150 ms") << 150;
        QTest::newRow("400 ms") << 400;
        QTest::newRow("1 s") << 1000;
    }

    void lateAnswersAreNeverAnotherRequests() {
        QFETCH(int, delayMs);
        Bench bench;
        auto& line = static_cast<SimCompax3Line&>(bench.transport.line());
        line.delayAnswers(delayMs);
        const Result<Compax3Identity> identity = bench.device.identity();
        QVERIFY2(identity.ok(), qPrintable(identity.error().message));
        QCOMPARE(identity->serial, QStringLiteral("C3-4711-0815"));
        QCOMPARE(*bench.device.readObject(kCompax3Position, false), QStringLiteral("0"));
        QCOMPARE(*bench.device.readObject(compax3SetTarget(3), false), QStringLiteral("300"));
        // A STOP of a jogging drive, its answers late: acknowledged, stopped.
        line.delayAnswers(0);
        QVERIFY(bench.device.motion(Compax3Motion::Enable).ok());
        QVERIFY(bench.device.motion(Compax3Motion::JogPlus).ok());
        line.delayAnswers(delayMs);
        const MotionStopReport report = bench.drive.motionControl()->stopAllMotion();
        QVERIFY2(report.allAcknowledged(), qPrintable(report.lines.first().detail));
        QVERIFY(!report.lines.first().nothingToStop);
        QVERIFY(!bench.sim().moving());
        QVERIFY(bench.sim().powered());
        QVERIFY2(report.lines.first().detail.startsWith(QLatin1String("powered, standing at")),
                 qPrintable(report.lines.first().detail));
        // Each was taken in the wait after its first attempt: none sent twice.
        QVERIFY(bench.drive.engine().stats().lateAnswersTaken >= 10);
        QCOMPARE(bench.drive.engine().stats().retries, 0);
    }

    void readsASetAsTheDriveHoldsIt() {
        Bench bench;
        bench.sim().setValue(compax3SetMode(6), QStringLiteral("2"));
        const Result<Compax3SetValues> set = bench.device.readSet(6);
        QVERIFY2(set.ok(), qPrintable(set.error().message));
        QCOMPARE(set->target, 600.0);
        QCOMPARE(set->velocity, 200.0);
        QCOMPARE(set->acceleration, 1000.0);
        QCOMPARE(set->mode, 2);
        QCOMPARE(set->modeText(), QStringLiteral("relative"));
        QVERIFY(!bench.device.readSet(32).ok());
    }

    void aFileNeverMovesTheAxis() {
        // Issue 27 item 4: a restore of a file holding the control word
        // (and a set store) sends nothing to either, says so, writes the rest.
        using namespace cambench::usecases;
        Bench bench;
        Compax3ParameterSet set;
        set.drive.info = bench.sim().infoString();
        set.drive.serial = *bench.device.readObject(kCompax3Serial);  // this drive's own set
        set.values = {{kCompax3ControlWord, QStringLiteral("$6103")},
                      {compax3StoreSet(1), QStringLiteral("$32")},
                      {compax3SetTarget(1), QStringLiteral("55")}};
        const Result<OutcomeTally> restored =
            restoreCompax3Parameters(bench.device, set, Compax3Dictionary::builtin(), {});
        QVERIFY2(restored.ok(), qPrintable(restored.error().message));
        for (const QByteArray& request : bench.sim().requests())
            QVERIFY2(!request.startsWith("O1100,3") && !request.startsWith("O1904"),
                     request.constData());
        QCOMPARE(restored->count(WriteState::NotSent), 2);
        QCOMPARE(restored->count(WriteState::Written), 1);
        QVERIFY(!restored->complete());  // never "done" with something skipped
        QVERIFY2(restored->lines().first().text.contains(QLatin1String("control word")),
                 qPrintable(restored->lines().first().text));
        QCOMPARE(bench.sim().value(compax3SetTarget(1)), QStringLiteral("55"));
        // A backup asked for them never saves them, whatever the dictionary.
        const Result<Compax3Backup> backup = takeCompax3Parameters(
            bench.device, {kCompax3ControlWord, compax3SetTarget(1)}, Compax3Dictionary::builtin());
        QCOMPARE(backup->set.values.size(), 1);
        QCOMPARE(backup->notSaved.size(), 1);
        // Typed on the Objects page: the control word is the Motion page's.
        const OutcomeTally typed = writeCompax3Objects(
            bench.device, {{kCompax3ControlWord, QStringLiteral("1"), QStringLiteral("1")}},
            Compax3Dictionary::builtin(), Compax3WriteSource::Typed);
        QCOMPARE(typed.count(WriteState::NotSent), 1);
        for (const QByteArray& request : bench.sim().requests())
            QVERIFY(!request.startsWith("O1100,3="));
    }

    void twoDrivesThatDifferInTypeAndObjects() {
        // Issue 29 item 2: one drive without set 0, one with it, of
        // another type: absent on both is equal; in the file but absent on
        // the target is said and not written.
        using namespace cambench::usecases;
        Bench lacking;
        Bench full(-1, -1, {}, QStringLiteral("S150V4"));
        const QList<Compax3ObjectId> set0 = {compax3SetTarget(0), compax3SetVelocity(0)};
        for (const Compax3ObjectId& id : set0) lacking.sim().removeObject(id);
        const QList<Compax3ObjectId> objects = Compax3Dictionary::builtin().parameters();

        const Result<Compax3Backup> own =
            takeCompax3Parameters(lacking.device, objects, Compax3Dictionary::builtin());
        QVERIFY2(own.ok(), qPrintable(own.error().message));
        QVERIFY(own->refused.isEmpty());
        QCOMPARE(own->set.absent, set0);
        QCOMPARE(own->set.values.size(), objects.size() - 2);
        const Result<Compax3Comparison> same =
            compareCompax3Parameters(lacking.device, own->set, Compax3Dictionary::builtin());
        QVERIFY(same->differences.isEmpty());
        QCOMPARE(same->absentOnBoth, 2);

        const Result<Compax3Backup> other =
            takeCompax3Parameters(full.device, objects, Compax3Dictionary::builtin());
        QVERIFY(other->set.absent.isEmpty());
        const Result<Compax3Comparison> differs =
            compareCompax3Parameters(lacking.device, other->set, Compax3Dictionary::builtin());
        QCOMPARE(differs->differences.size(), 2);
        QCOMPARE(differs->differences.first().error, QStringLiteral("not on this drive"));
        Compax3RestoreOptions forced;
        forced.force = true;                             // the types differ
        forced.replacement = ReplacementConsent::any();  // and so the drives
        const qsizetype from = lacking.sim().requests().size();
        const Result<OutcomeTally> restored = restoreCompax3Parameters(
            lacking.device, other->set, Compax3Dictionary::builtin(), forced);
        QVERIFY2(restored.ok(), qPrintable(restored.error().message));
        QCOMPARE(restored->count(WriteState::NotSent), 2);
        QVERIFY(restored->lines().first().text.contains(QLatin1String("not on this drive")));
        for (const QByteArray& request : lacking.sim().requests().mid(from))
            QVERIFY(!request.startsWith("O1901,0=") && !request.startsWith("O1902,0="));
        // The other way: absent in the file, present here: said, left as it is.
        const Result<Compax3Comparison> extra =
            compareCompax3Parameters(full.device, own->set, Compax3Dictionary::builtin());
        QCOMPARE(extra->differences.size(), 2);
        QVERIFY(extra->differences.first().absentInFile);
    }

    // Issue 29: the public client python-dvg-devices'
    // Compax3_servo_protocol_RS232 (its demo's order), replayed as it
    // writes each line (lower case 'o', '.' between index and subindex,
    // decimal control words), with the answers it expects.
    void replaysThePublicClientsSequence() {
        Bench bench;
        SimCompax3Drive& drive = bench.sim();
        qint64 now = 0;
        auto ask = [&drive, &now](const char* request) {
            now += 20;
            return drive.answer(QByteArray(request), now);
        };
        // Identify: the info string starts with "Compax3", then the serial.
        QVERIFY(ask("_?").startsWith("Compax3"));
        QCOMPARE(ask("o1.4"), QByteArray("C3-4711-0815"));
        QCOMPARE(ask("o550.1"), QByteArray("1"));
        QCOMPARE(ask("o680.5"), QByteArray("0"));
        QCOMPARE(ask("o1000.3"), QByteArray("1285"));  // powerless, no error, I0 and I2
        // Acknowledge: a rising edge of b0.
        QCOMPARE(ask("o1100.3=0"), QByteArray(">"));
        QCOMPARE(ask("o1100.3=1"), QByteArray(">"));
        QCOMPARE(ask("o1000.3").toInt() & 0x0400, 0);  // powered
        // Store set 2's values, then 1904.2 = $32 (store profile).
        for (const char* write :
             {"o1901.2=-180.00", "o1902.2=100.00", "o1905.2=1", "o1906.2=100.00", "o1907.2=100.00",
              "o1908.2=1000000.00", "o1904.2=$32"})
            QCOMPARE(ask(write), QByteArray(">"));
        QCOMPARE(drive.value(compax3SetTarget(2)), QStringLiteral("-180"));
        // Activate set 2: start bit low (16899), then high (25091).
        QCOMPARE(ask("o1100.3=16899"), QByteArray(">"));
        QCOMPARE(ask("o1100.3=25091"), QByteArray(">"));
        QVERIFY(drive.moving());
        now += 5000;  // 180 units at 100/s
        QCOMPARE(ask("o680.5"), QByteArray("-180"));
        QCOMPARE(ask("o1000.4"), QByteArray("2"));
        // Jog + and −, each from $4003 (run, stop bits set), then stop with
        // power kept ($4003) and with power removed (0).
        QCOMPARE(ask("o1100.3=16387"), QByteArray(">"));
        QCOMPARE(ask("o1100.3=16391"), QByteArray(">"));  // jog +
        QVERIFY(drive.moving());
        QCOMPARE(ask("o1100.3=16387"), QByteArray(">"));
        QVERIFY(!drive.moving());
        QCOMPARE(ask("o1100.3=16395"), QByteArray(">"));  // jog −
        QVERIFY(drive.moving());
        QCOMPARE(ask("o1100.3=16387"), QByteArray(">"));  // stop, keep power
        QVERIFY(!drive.moving());
        QCOMPARE(ask("o1100.3=0"), QByteArray(">"));  // power off
        QVERIFY(ask("o1000.3").toInt() & 0x0400);
        // A refusal: "!" and four hex digits, which the client prints.
        const QByteArray refusal = ask("o1905.2=7");
        QCOMPARE(refusal, QByteArray("!0004"));
        QCOMPARE(parseCompax3Reply(refusal)->kind, Compax3Reply::Error);
        QCOMPARE(ask("o4321.1"), QByteArray("!0002"));
    }
};

QTEST_GUILESS_MAIN(TestCompax3Drive)
#include "tst_compax3_drive.moc"
