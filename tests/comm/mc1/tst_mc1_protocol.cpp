// Issue 14, point 1 and 3: MC-1 telegrams of the four variants, answers and
// the address arithmetic, against docs/protocols/mc1.md's test vectors (worked
// by hand from the manual's chapter 5 examples) and tables 47 and 48.
#include "comm/engine/cr_line_backend.h"
#include "comm/mc1/mc1_address.h"
#include "comm/mc1/mc1_ascii.h"
#include "comm/mc1/mc1_catalogue.h"

#include <QTest>

using namespace cambench;
using namespace cambench::comm;

namespace {

QByteArray bytes(const char* hex) {
    return QByteArray::fromHex(QByteArray(hex).replace(' ', ""));
}

QByteArray request(Mc1Variant variant, Mc1Op op, const QByteArray& parameters) {
    const Mc1Telegram* telegram = mc1Find(variant, op);
    if (!telegram) return {};
    const Result<QByteArray> built = mc1Request(*telegram, parameters);
    return built ? *built : QByteArray();
}

QByteArray pair(quint8 a, quint8 b) {
    QByteArray out;
    out.append(char(a));
    out.append(char(b));
    return out;
}

// The request that reads or flips `text`'s bit on `variant`.
QByteArray readBit(Mc1Variant variant, const QString& text) {
    const Mc1BitAddress at = *mc1BitAddress(*parseMc1Point(text), isMc200(variant));
    return at.external ? request(variant, Mc1Op::ReadByteExternal, pair(at.address, at.page))
                       : request(variant, Mc1Op::ReadByteInternal, QByteArray(1, char(at.address)));
}

QByteArray writeBit(Mc1Variant variant, const QString& text, bool on) {
    const Mc1BitAddress at = *mc1BitAddress(*parseMc1Point(text), isMc200(variant));
    // 2^bit sets the bit, NOT 2^bit clears it.
    const quint8 flag = on ? at.mask() : quint8(~at.mask());
    return request(variant, at.external ? Mc1Op::WriteBitExternal : Mc1Op::WriteBitInternal,
                   pair(at.address, flag));
}

}  // namespace

class TestMc1Protocol : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void testVectorsFromTheNotes() {
        const Mc1Variant mc200 = Mc1Variant::Mc200V2;
        QCOMPARE(readBit(mc200, QStringLiteral("M2711")), bytes("22 74 52"));
        QCOMPARE(writeBit(mc200, QStringLiteral("M2327"), true), bytes("3B 9D 22 40"));
        QCOMPARE(writeBit(mc200, QStringLiteral("M2327"), false), bytes("3B 1C 22 BF"));
        QCOMPARE(readBit(mc200, QStringLiteral("M841")), bytes("A3 0C 69 00"));
        QCOMPARE(readBit(mc200, QStringLiteral("E122")), bytes("22 11 EF"));
        QCOMPARE(readBit(mc200, QStringLiteral("A122")), bytes("22 F1 CF"));
        QCOMPARE(request(Mc1Variant::Mc100V1, Mc1Op::ReadVariable, mc1LittleEndian(1, 2)),
                 bytes("C3 C4 01 00"));
        QCOMPARE(request(mc200, Mc1Op::ProgramStatus, {}), bytes("92 92 00"));
        QCOMPARE(request(mc200, Mc1Op::AxisCommand, bytes("01 06")), bytes("9B A2 01 06"));
    }

    void answersAreTakenWithTheirChecksum() {
        // MC100 RDVAR answer 0x123456.
        const Mc1Telegram& rdvar = *mc1Find(Mc1Variant::Mc100V1, Mc1Op::ReadVariable);
        const Mc1Expectation expected = mc1ExpectedAnswer(rdvar, mc1LittleEndian(1, 2));
        QCOMPARE(expected.opcode, quint8(0x04));
        QCOMPARE(expected.length, 5);
        QByteArray line = bytes("FF FF 04 A0 56");  // sync bytes first, then a part
        QVERIFY(!takeMc1Answer(line, expected));
        line += bytes("34 12");
        const auto answer = takeMc1Answer(line, expected);
        QVERIFY(answer && answer->ok());
        QCOMPARE((*answer)->kind, Mc1Answer::Kind::Data);
        QCOMPARE(mc1FromLittleEndian((*answer)->data, true), qint64(0x123456));
        QVERIFY(line.isEmpty());

        // Status: present, running, PC 0x1234.
        const Mc1Telegram& status = *mc1Find(Mc1Variant::Mc200V2, Mc1Op::ProgramStatus);
        QByteArray reply = bytes("94 DD 03 34 12");
        const auto flags = takeMc1Answer(reply, mc1ExpectedAnswer(status, {}));
        QVERIFY(flags && flags->ok());
        QCOMPARE((*flags)->data, bytes("03 34 12"));

        // ACK and NAK are one byte; a bad checksum or a foreign opcode is said.
        const Mc1Expectation ack;
        QByteArray nak = bytes("87");
        QCOMPARE((*takeMc1Answer(nak, ack))->kind, Mc1Answer::Kind::Nak);
        QByteArray damaged = bytes("04 A1 56 34 12");
        const auto bad = takeMc1Answer(damaged, expected);
        QVERIFY(bad && !bad->ok());
        QVERIFY2(bad->error().message.contains(QLatin1String("checksum")),
                 qPrintable(bad->error().message));
        QByteArray foreign = bytes("05 00");
        QVERIFY(!takeMc1Answer(foreign, expected)->ok());
    }

    void negativeValuesAreTwosComplement() {
        QCOMPARE(mc1LittleEndian(-5, 3), bytes("FB FF FF"));
        QCOMPARE(mc1FromLittleEndian(bytes("FB FF FF"), true), qint64(-5));
        QCOMPARE(mc1FromLittleEndian(bytes("FB FF FF FF"), true), qint64(-5));
        QCOMPARE(mc1FromLittleEndian(bytes("FB FF FF"), false), qint64(0xFFFFFB));
    }

    void variantsKnowTheirOwnTelegrams() {
        // D5 is RDBLOCK on an MC100 V2 and RDMEM6 on an MC200, with the same answer.
        QVERIFY(mc1Find(Mc1Variant::Mc100V2, Mc1Op::ReadBlock));
        QVERIFY(!mc1Find(Mc1Variant::Mc100V1, Mc1Op::ReadBlock));
        QVERIFY(!mc1Find(Mc1Variant::Mc200V2, Mc1Op::ReadBlock));
        QCOMPARE(mc1Find(Mc1Variant::Mc200V1, Mc1Op::ReadMemory6)->opcode, quint8(0xD5));
        // RDVAR answers 24 bits on an MC100, 32 on an MC200.
        QCOMPARE(mc1Find(Mc1Variant::Mc100V2, Mc1Op::ReadVariable)->answerOpcode, quint8(0x04));
        QCOMPARE(mc1Find(Mc1Variant::Mc200V1, Mc1Op::ReadVariable)->answerOpcode, quint8(0x05));
        QVERIFY(!mc1Find(Mc1Variant::Mc200V1, Mc1Op::ProgramStart));
        QVERIFY(mc1Find(Mc1Variant::Mc200V2, Mc1Op::AxisDataCommand));
        QVERIFY(!mc1Find(Mc1Variant::Mc100V2, Mc1Op::WriteVariable32));
        // Every row's request follows (opcode & 7) + 1 unless marked.
        for (Mc1Variant variant : allMc1Variants()) {
            for (const Mc1Telegram& t : mc1Catalogue(variant)) {
                if (t.lengthException) continue;
                const int length = 2 + (t.command >= 0 ? 1 : 0) + t.requestData;
                QVERIFY2(length == mc1FormulaLength(t.opcode), t.name);
            }
        }
        QVERIFY(!mc1Request(*mc1Find(Mc1Variant::Mc100V1, Mc1Op::ReadVariable), bytes("01")));
        QCOMPARE(mc1VariantFromKey(QStringLiteral("MC200v2")), Mc1Variant::Mc200V2);
        QCOMPARE(mc1VariantName(Mc1Variant::Mc100V2), QStringLiteral("MC100 V2"));
    }

    void retriesFollowWhatATelegramDoes() {
        const Mc1Variant v = Mc1Variant::Mc200V2;
        QCOMPARE(mc1Find(v, Mc1Op::ReadVariable)->retry, Mc1Retry::Read);
        QCOMPARE(mc1Find(v, Mc1Op::ProgramStop)->retry, Mc1Retry::Idempotent);
        for (Mc1Op op :
             {Mc1Op::ProgramStart, Mc1Op::ProgramStep, Mc1Op::Reset, Mc1Op::WriteBitInternal,
              Mc1Op::WriteBitExternal, Mc1Op::AxisCommand, Mc1Op::AxisDataCommand, Mc1Op::Flash})
            QCOMPARE(mc1Find(v, op)->retry, Mc1Retry::Never);
    }

    void mc100AddressesFollowTables47And48() {
        const auto at = [](const char* text) {
            return mc1BitAddress(*parseMc1Point(QString::fromLatin1(text)), false);
        };
        QCOMPARE(*at("M500"), (Mc1BitAddress{false, 0, 0x2B, 0}));
        QCOMPARE(*at("M1088"), (Mc1BitAddress{false, 0, 0xD7, 7}));
        QCOMPARE(*at("M959"), (Mc1BitAddress{false, 0, 0xCD, 6}));
        QVERIFY(!at("M723"));  // printed without an address
        QVERIFY(!at("M543"));  // not in the table
        QCOMPARE(*at("E500"), (Mc1BitAddress{false, 0, 0xB8, 0}));
        QCOMPARE(*at("E579"), (Mc1BitAddress{false, 0, 0xC9, 3}));
        // Input 193 shares 0xB8 with E500, as printed.
        QCOMPARE(at("E193")->address, quint8(0xB8));
        QCOMPARE(*at("A128"), (Mc1BitAddress{false, 0, 0x9F, 7}));
        QVERIFY(!at("A129"));
        // External flags fill page 0x7F: M499 and M2000 are neighbours.
        QCOMPARE(*at("M499"), (Mc1BitAddress{true, 0x7F, 0x3E, 2}));
        QCOMPARE(*at("M2000"), (Mc1BitAddress{true, 0x7F, 0x3E, 3}));
        QCOMPARE(*at("M3548"), (Mc1BitAddress{true, 0x7F, 0xFF, 7}));
        const Result<Mc1BitAddress> missing = at("M1500");
        QVERIFY2(missing.error().message.contains(QLatin1String("MC100")),
                 qPrintable(missing.error().message));
    }

    void mc200Addresses() {
        const auto at = [](const char* text) {
            return mc1BitAddress(*parseMc1Point(QString::fromLatin1(text)), true);
        };
        QCOMPARE(*at("M2049"), (Mc1BitAddress{false, 0, 0x00, 0}));
        QCOMPARE(*at("M3584"), (Mc1BitAddress{false, 0, 0xBF, 7}));
        QCOMPARE(*at("M2048"), (Mc1BitAddress{true, 0x00, 0xFF, 7}));
        QCOMPARE(*at("A256"), (Mc1BitAddress{false, 0, 0xDF, 7}));
        QCOMPARE(*at("E1"), (Mc1BitAddress{false, 0, 0xE0, 0}));
        QVERIFY(!at("M3585"));
        QVERIFY(!parseMc1Point(QStringLiteral("X12")));
        QCOMPARE(*parseMc1Point(QStringLiteral(" m 2327")), (Mc1Point{Mc1Area::Flag, 2327}));
    }

    void mc100AsciiBothWays() {
        QCOMPARE(mc1AsciiReadVariable(12), QByteArray("V12=?\r"));
        QCOMPARE(*mc1AsciiWriteVariable(12, -5), QByteArray("V12=-5\r"));
        QVERIFY(!mc1AsciiWriteVariable(1, 1 << 23));  // beyond 24 bits
        QCOMPARE(mc1AsciiReadPoint({Mc1Area::Input, 122}), QByteArray("E122=?\r"));
        QCOMPARE(*mc1AsciiWritePoint({Mc1Area::Output, 3}, true), QByteArray("A3=1\r"));
        QVERIFY(!mc1AsciiWritePoint({Mc1Area::Input, 3}, true));

        QByteArray line = "-12345\r\nOK";
        QCOMPARE(*mc1AsciiValue(*takeCrLine(line)), -12345);
        QVERIFY(!takeCrLine(line));  // "OK" still without its CR
        line += "\r";
        QVERIFY(mc1AsciiOk(*takeCrLine(line)).ok());  // the LF before it dropped
        const Result<bool> refused = mc1AsciiBit("ERR");
        QCOMPARE(refused.error().kind, ErrorKind::DeviceError);
        QVERIFY(!mc1AsciiBit("2"));

        // The controller's side: lower case and spaces accepted.
        const auto request = parseMc1AsciiRequest(" m 2327 = 1");
        QVERIFY(request);
        QCOMPARE(request->point, (Mc1Point{Mc1Area::Flag, 2327}));
        QCOMPARE(*request->value, 1);
        QVERIFY(!parseMc1AsciiRequest("v12=?")->value);
        QVERIFY(!parseMc1AsciiRequest("X1=?"));
    }
};

QTEST_APPLESS_MAIN(TestMc1Protocol)
#include "tst_mc1_protocol.moc"
