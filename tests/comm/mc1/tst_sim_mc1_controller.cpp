// Issue 14, point 7 (first part): the simulated MC100/MC200 answers the
// client's own telegrams (comm/mc1) as docs/protocols/mc1.md says a real one
// does, for each variant.
#include "comm/mc1/mc1_address.h"
#include "comm/mc1/mc1_catalogue.h"
#include "comm/sim/mc1/sim_mc1_controller.h"

#include <QTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

// Sends `op` with `parameters` and takes the answer as the client would.
Result<Mc1Answer> exchange(SimMc1Controller& device, Mc1Op op, const QByteArray& parameters,
                           qint64 nowMs = 0) {
    const Mc1Telegram* telegram = mc1Find(device.variant(), op);
    if (!telegram) return Error::usage(QStringLiteral("not in this variant"));
    const QByteArray request = *mc1Request(*telegram, parameters);
    QByteArray line = device.handle(request, nowMs);
    const auto answer = takeMc1Answer(line, mc1ExpectedAnswer(*telegram, parameters));
    if (!answer) return Error::communication(QStringLiteral("incomplete answer"));
    return *answer;
}

QByteArray le(qint64 value, int bytes) {
    return mc1LittleEndian(value, bytes);
}

}  // namespace

class TestSimMc1Controller : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void variablesKeepTheirWidth() {
        SimMc1Controller mc100(Mc1Variant::Mc100V1);
        QCOMPARE(exchange(mc100, Mc1Op::WriteVariable, le(12, 2) + le(-5, 3))->kind,
                 Mc1Answer::Kind::Ack);
        const Result<Mc1Answer> read = exchange(mc100, Mc1Op::ReadVariable, le(12, 2));
        QCOMPARE(read->data.size(), 3);
        QCOMPARE(mc1FromLittleEndian(read->data, true), qint64(-5));

        SimMc1Controller mc200(Mc1Variant::Mc200V2);
        QCOMPARE(exchange(mc200, Mc1Op::WriteVariable32, le(3, 2) + le(-100000, 4))->kind,
                 Mc1Answer::Kind::Ack);
        QCOMPARE(mc1FromLittleEndian(exchange(mc200, Mc1Op::ReadVariable, le(3, 2))->data, true),
                 qint64(-100000));
        // CE on an MC200 sign-extends the 24-bit value (provisional P3).
        exchange(mc200, Mc1Op::WriteVariable, le(4, 2) + le(-2, 3));
        QCOMPARE(mc200.variable(4), qint64(-2));
    }

    void bitsAreSetAndClearedWhereTheAddressArithmeticSays() {
        for (Mc1Variant variant : {Mc1Variant::Mc100V1, Mc1Variant::Mc200V2}) {
            SimMc1Controller device(variant);
            const QString text = isMc200(variant) ? QStringLiteral("M2327") : QStringLiteral("M12");
            const Mc1BitAddress a = *mc1BitAddress(*parseMc1Point(text), isMc200(variant));
            const Mc1Op write = a.external ? Mc1Op::WriteBitExternal : Mc1Op::WriteBitInternal;
            QByteArray set;
            set.append(char(a.address));
            set.append(char(a.mask()));
            QCOMPARE(exchange(device, write, set)->kind, Mc1Answer::Kind::Ack);
            QByteArray read;
            read.append(char(a.address));
            if (a.external) read.append(char(a.page));
            const Mc1Op readOp = a.external ? Mc1Op::ReadByteExternal : Mc1Op::ReadByteInternal;
            QCOMPARE(quint8(exchange(device, readOp, read)->data.at(0)), a.mask());
            QByteArray clear;
            clear.append(char(a.address));
            clear.append(char(~a.mask()));
            exchange(device, write, clear);
            QCOMPARE(quint8(exchange(device, readOp, read)->data.at(0)), quint8(0));
            // Two bits at once is no WRBIT: NAK.
            QByteArray two;
            two.append(char(a.address));
            two.append(char(0x03));
            QCOMPARE(exchange(device, write, two)->kind, Mc1Answer::Kind::Nak);
        }
    }

    void badTelegramsAreNaked() {
        SimMc1Controller mc100(Mc1Variant::Mc100V1);
        QByteArray request = mc1Telegram(0xC3, le(1, 2));
        request[1] = char(request.at(1) + 1);  // checksum off by one
        QCOMPARE(mc100.handle(request, 0), QByteArray(1, char(kMc1Nak)));
        // An MC100 V1 knows no RDBLOCK; an MC200 V1 no SYSDATA.
        QCOMPARE(mc100.requestLength(QByteArray(1, char(0xD5))), -1);
        SimMc1Controller mc200v1(Mc1Variant::Mc200V1);
        QCOMPARE(mc200v1.requestLength(QByteArray::fromHex("929200")), -1);
        // WRMEM's length comes with its n.
        SimMc1Controller mc200(Mc1Variant::Mc200V2);
        QCOMPARE(mc200.requestLength(QByteArray::fromHex("DE00")), 0);
        QCOMPARE(mc200.requestLength(QByteArray::fromHex("DE00100003")), 8);
    }

    void memoryAndProgram() {
        SimMc1Controller mc200(Mc1Variant::Mc200V2);
        const QByteArray bytes = QByteArray::fromHex("0102030405");
        QCOMPARE(exchange(mc200, Mc1Op::WriteMemory, le(0x100, 2) + QByteArray(1, 5) + bytes)->kind,
                 Mc1Answer::Kind::Ack);
        QCOMPARE(exchange(mc200, Mc1Op::ReadMemory, le(0x100, 2) + QByteArray(1, 5))->data, bytes);
        QCOMPARE(exchange(mc200, Mc1Op::ReadMemory6, le(0x100, 2))->data, bytes + '\0');

        QCOMPARE(exchange(mc200, Mc1Op::ProgramStatus, {})->data.at(0), char(0x01));  // present
        exchange(mc200, Mc1Op::ProgramStart, {});
        QCOMPARE(exchange(mc200, Mc1Op::ProgramStatus, {})->data.at(0), char(0x03));  // running
        exchange(mc200, Mc1Op::ProgramStop, {});
        QVERIFY(!mc200.running());

        // Flash: save, change, load brings the saved variables back.
        mc200.setVariable(1, 7);
        exchange(mc200, Mc1Op::Flash, QByteArray(1, 1));
        mc200.setVariable(1, 8);
        exchange(mc200, Mc1Op::Flash, QByteArray(1, 2));
        QCOMPARE(mc200.variable(1), qint64(7));
    }

    void axesMoveWithTimeAndStop() {
        SimMc1Controller mc200(Mc1Variant::Mc200V2);
        QByteArray move;
        move.append(char(1));
        move.append(char(0x03));  // start to absolute position
        QCOMPARE(exchange(mc200, Mc1Op::AxisDataCommand, move + le(1000, 4), 0)->kind,
                 Mc1Answer::Kind::Ack);
        QCOMPARE(mc200.axisPosition(1, 500), 500);  // 1000 units/s
        QVERIFY(mc200.axisMoving(1, 500));
        QByteArray stop;
        stop.append(char(1));
        stop.append(char(0x08));
        exchange(mc200, Mc1Op::AxisCommand, stop, 600);
        QCOMPARE(mc200.axisPosition(1, 900), 600);
        QVERIFY(!mc200.axisMoving(1, 900));
        // A stop may be repeated after a lost answer; a move may not.
        QCOMPARE(mc1AxisRetry(Mc1Op::AxisCommand, 0x08), Mc1Retry::Idempotent);
        QCOMPARE(mc1AxisRetry(Mc1Op::AxisDataCommand, 0x04), Mc1Retry::Never);
        // Axis 9 does not exist.
        QByteArray home;
        home.append(char(9));
        home.append(char(0x06));
        QCOMPARE(exchange(mc200, Mc1Op::AxisCommand, home)->kind, Mc1Answer::Kind::Nak);
    }
};

QTEST_APPLESS_MAIN(TestSimMc1Controller)
#include "tst_sim_mc1_controller.moc"
