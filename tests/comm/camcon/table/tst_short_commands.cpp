#include "comm/camcon/table/short_commands.h"

#include <QtTest>

using namespace cambench;
using namespace cambench::comm::table;

namespace {

QByteArray hex(const char* text) {
    return QByteArray::fromHex(text);
}

}  // namespace

class TestShortCommands : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void encodesStatusQuery();
    void statusQueryTakesVirtualInputsInWholeWords();
    void encodesErrorResetAndProgramChange();
    void encodesTrackRead();
    void encodesTrackWriteAsTheManualShows();
    void trackWriteRefusesWhatDoesNotFit();
    void encodesDeadTimeReadAndWrite();
    void decodesStatusReply();
    void statusReplyRoundTrips();
    void statusReplyErrors();
    void decodesAcknowledgements();
    void deadTimeWriteAcceptsTheManualsTypo();
    void unknownCommandReplyIsNotUnderstood();
    void decodesTrackReply();
    void trackReplyMustEchoTheRequest();
    void decodesDeadTimeReply();
    void tellsShortCommandsFromRk512();
    void positionsAreSigned16Bit();
};

void TestShortCommands::encodesStatusQuery() {
    QCOMPARE(*encodeStatusRequest(), QByteArray("?\x01"));
}

void TestShortCommands::statusQueryTakesVirtualInputsInWholeWords() {
    QList<bool> inputs(16, false);
    inputs[0] = true;  // V1: bit 0 of the first byte
    inputs[9] = true;  // V10: bit 1 of the second byte
    QCOMPARE(encodeStatusRequest(inputs)->toHex(' '), hex("3F01 0102").toHex(' '));
    QList<bool> all(32, true);
    QCOMPARE(*encodeStatusRequest(all), QByteArray("?\x01") + QByteArray(4, '\xFF'));
    const Result<QByteArray> odd = encodeStatusRequest(QList<bool>(20, true));
    QCOMPARE(odd.error().kind, ErrorKind::Usage);
    QVERIFY2(odd.error().message.contains("multiple of 16"), qPrintable(odd.error().message));
    QVERIFY(encodeStatusRequest(QList<bool>(496, true)).ok());
    QCOMPARE(encodeStatusRequest(QList<bool>(512, true)).error().kind, ErrorKind::Usage);
}

void TestShortCommands::encodesErrorResetAndProgramChange() {
    QCOMPARE(encodeErrorResetRequest(), QByteArray("!\x02"));
    QCOMPARE(encodeProgramChangeRequest(5)->toHex(' '), hex("2103 0005").toHex(' '));
    QCOMPARE(encodeProgramChangeRequest(32767)->toHex(' '), hex("2103 7FFF").toHex(' '));
    QCOMPARE(encodeProgramChangeRequest(-1).error().kind, ErrorKind::Usage);
    QCOMPARE(encodeProgramChangeRequest(70000).error().kind, ErrorKind::Usage);
}

void TestShortCommands::encodesTrackRead() {
    QCOMPARE(encodeReadTrackRequest(3, 7)->toHex(' '), hex("3F04 0003 07 00").toHex(' '));
    QCOMPARE(encodeReadTrackRequest(3, 0).error().kind, ErrorKind::Usage);  // outputs from 1
    QCOMPARE(encodeReadTrackRequest(3, 256).error().kind, ErrorKind::Usage);
}

void TestShortCommands::encodesTrackWriteAsTheManualShows() {
    // Manual 5.5: program, output 1 with 1 cam, output 2 with 2 cams, FFFF.
    const QList<Track> tracks{{1, {{10, 20}}}, {2, {{30, 40}, {50, 60}}}};
    const Result<QByteArray> telegram = encodeWriteTracksRequest(1, tracks);
    QVERIFY(telegram.ok());
    QCOMPARE(telegram->toHex(' '),
             hex("2105 0001 0101 000A 0014 0202 001E 0028 0032 003C FFFF").toHex(' '));
    // The manual's send length for this example is 0x16 bytes.
    QCOMPARE(telegram->size(), 0x16);
    // No cams: the output's track is cleared.
    QCOMPARE(encodeWriteTracksRequest(0, {{4, {}}})->toHex(' '),
             hex("2105 0000 0400 FFFF").toHex(' '));
}

void TestShortCommands::trackWriteRefusesWhatDoesNotFit() {
    QList<Cam> fourteen;
    for (int i = 0; i < 14; ++i) fourteen.append({i * 10, i * 10 + 5});
    const Result<QByteArray> full = encodeWriteTracksRequest(0, {{1, fourteen}});
    QVERIFY(full.ok());
    QCOMPARE(full->size(), kMaxShortTelegramBytes);
    QList<Cam> fifteen = fourteen;
    fifteen.append({200, 210});
    const Result<QByteArray> tooMany = encodeWriteTracksRequest(0, {{1, fifteen}});
    QCOMPARE(tooMany.error().kind, ErrorKind::Usage);
    QVERIFY2(tooMany.error().message.contains("14"), qPrintable(tooMany.error().message));
    const Result<QByteArray> tooFar = encodeWriteTracksRequest(0, {{3, {{10, 40000}}}});
    QCOMPARE(tooFar.error().kind, ErrorKind::Usage);
    QVERIFY2(tooFar.error().message.contains("Output 3, cam 1: switch-off point 40000"),
             qPrintable(tooFar.error().message));
    QCOMPARE(encodeWriteTracksRequest(0, {{0, {{1, 2}}}}).error().kind, ErrorKind::Usage);
}

void TestShortCommands::encodesDeadTimeReadAndWrite() {
    QCOMPARE(encodeReadDeadTimeRequest(5)->toHex(' '), hex("3F06 05 00").toHex(' '));
    QCOMPARE(encodeWriteDeadTimeRequest(5, 1234)->toHex(' '), hex("2107 05 00 04D2").toHex(' '));
    QCOMPARE(encodeWriteDeadTimeRequest(5, 65535)->toHex(' '), hex("2107 05 00 FFFF").toHex(' '));
    QCOMPARE(encodeWriteDeadTimeRequest(5, 65536).error().kind, ErrorKind::Usage);
    QCOMPARE(encodeWriteDeadTimeRequest(5, -1).error().kind, ErrorKind::Usage);
    QCOMPARE(encodeReadDeadTimeRequest(0).error().kind, ErrorKind::Usage);
}

void TestShortCommands::decodesStatusReply() {
    // Actual value 100, speed 10, program 3, status 0, 20 outputs of which
    // 1, 3 and 20 are on; the output bits fill whole words.
    const QByteArray reply = hex("3A01 0064 000A 0003 00 14 0500 0800");
    const Result<ShortStatus> status = decodeStatusReply(reply);
    QVERIFY2(status.ok(), qPrintable(status.error().message));
    QCOMPARE(status->actualValue, 100);
    QCOMPARE(status->speed, 10);
    QCOMPARE(status->program, 3);
    QCOMPARE(status->deviceStatus, 0);
    QCOMPARE(status->outputCount, 20);
    QList<bool> expected(20, false);
    expected[0] = expected[2] = expected[19] = true;
    QCOMPARE(status->outputs, expected);
    QCOMPARE(shortDeviceStatusText(status->deviceStatus), QStringLiteral("OK"));
    QCOMPARE(shortDeviceStatusText(2), QStringLiteral("actual-value error 2"));
    QCOMPARE(shortDeviceStatusText(4), QStringLiteral("output error"));
}

void TestShortCommands::statusReplyRoundTrips() {
    ShortStatus status;
    status.actualValue = -20;
    status.speed = 300;
    status.program = 12;
    status.deviceStatus = 4;
    status.outputCount = 20;
    status.outputs = QList<bool>(20, false);
    status.outputs[0] = status.outputs[2] = status.outputs[19] = true;
    const Result<QByteArray> reply = encodeStatusReply(status);
    QVERIFY(reply.ok());
    QCOMPARE(reply->toHex(' '), hex("3A01 FFEC 012C 000C 04 14 0500 0800").toHex(' '));
    QCOMPARE(*decodeStatusReply(*reply), status);
}

void TestShortCommands::statusReplyErrors() {
    QCOMPARE(decodeStatusReply(hex("3A01 0064 000A 0003 00")).error().kind,
             ErrorKind::Communication);
    // 20 outputs need 3 bytes of bits.
    QCOMPARE(decodeStatusReply(hex("3A01 0064 000A 0003 00 14 0500")).error().kind,
             ErrorKind::Communication);
    QCOMPARE(decodeStatusReply(hex("3A04 0064 000A 0003 00 00")).error().kind,
             ErrorKind::Communication);
    QCOMPARE(decodeStatusReply(hex("3F01 0064 000A 0003 00 00")).error().kind,
             ErrorKind::Communication);
    QCOMPARE(decodeStatusReply({}).error().kind, ErrorKind::Communication);
}

void TestShortCommands::decodesAcknowledgements() {
    for (ShortCommand command : {ShortCommand::ErrorReset, ShortCommand::ProgramChange,
                                 ShortCommand::WriteTracks, ShortCommand::WriteDeadTime}) {
        const QByteArray ok = encodeAcknowledgement(command, true);
        QCOMPARE(ok, QByteArray(":") + char(command) + "OK");
        QVERIFY(decodeAcknowledgement(command, ok).ok());
        const Status refused =
            decodeAcknowledgement(command, encodeAcknowledgement(command, false));
        QVERIFY(!refused.ok());
        QCOMPARE(refused.error().kind, ErrorKind::DeviceError);
        QVERIFY2(refused.error().message.contains("\"ER\""), qPrintable(refused.error().message));
    }
    const Status program = decodeAcknowledgement(ShortCommand::ProgramChange, QByteArray(":\x03"
                                                                                         "ER"));
    QVERIFY2(program.error().message.contains("program number"),
             qPrintable(program.error().message));
    QCOMPARE(decodeAcknowledgement(ShortCommand::ProgramChange, QByteArray(":\x03"
                                                                           "OX"))
                 .error()
                 .kind,
             ErrorKind::Communication);
    QCOMPARE(decodeAcknowledgement(ShortCommand::ProgramChange, QByteArray(":\x02"
                                                                           "OK"))
                 .error()
                 .kind,
             ErrorKind::Communication);
    QCOMPARE(decodeAcknowledgement(ShortCommand::ErrorReset, QByteArray(":")).error().kind,
             ErrorKind::Communication);
}

void TestShortCommands::deadTimeWriteAcceptsTheManualsTypo() {
    // The device side answers with the right number ...
    QCOMPARE(encodeAcknowledgement(ShortCommand::WriteDeadTime, true), QByteArray(":\x07"
                                                                                  "OK"));
    // ... and the PC also takes the number the manual prints (notes 10).
    QVERIFY(decodeAcknowledgement(ShortCommand::WriteDeadTime, QByteArray(":\x07"
                                                                          "OK"))
                .ok());
    QVERIFY(decodeAcknowledgement(ShortCommand::WriteDeadTime, QByteArray(":\x05"
                                                                          "OK"))
                .ok());
    QCOMPARE(decodeAcknowledgement(ShortCommand::WriteDeadTime, QByteArray(":\x05"
                                                                           "ER"))
                 .error()
                 .kind,
             ErrorKind::DeviceError);
    // Only in that direction: 0x05 is not answered with 0x07.
    QCOMPARE(decodeAcknowledgement(ShortCommand::WriteTracks, QByteArray(":\x07"
                                                                         "OK"))
                 .error()
                 .kind,
             ErrorKind::Communication);
}

void TestShortCommands::unknownCommandReplyIsNotUnderstood() {
    QCOMPARE(encodeUnknownCommandReply(), QByteArray(":Z"));
    const Status status = decodeAcknowledgement(ShortCommand::WriteDeadTime, ":Z");
    QCOMPARE(status.error().kind, ErrorKind::NotUnderstood);
    QVERIFY2(status.error().message.contains("dead-time write 0x07"),
             qPrintable(status.error().message));
    QCOMPARE(decodeStatusReply(":Z").error().kind, ErrorKind::NotUnderstood);
    QCOMPARE(decodeReadTrackReply(":Z", 1, 1).error().kind, ErrorKind::NotUnderstood);
    QCOMPARE(decodeReadDeadTimeReply(":Z", 1).error().kind, ErrorKind::NotUnderstood);
}

void TestShortCommands::decodesTrackReply() {
    const QByteArray reply = hex("3A04 0003 07 02 000A 0014 FFF6 0005");
    const Result<Track> track = decodeReadTrackReply(reply, 3, 7);
    QVERIFY2(track.ok(), qPrintable(track.error().message));
    QCOMPARE(*track, (Track{7, {{10, 20}, {-10, 5}}}));
    QCOMPARE(*encodeReadTrackReply(3, *track), reply);
    const Result<Track> empty = decodeReadTrackReply(hex("3A04 0003 07 00"), 3, 7);
    QVERIFY(empty.ok() && empty->cams.isEmpty());
}

void TestShortCommands::trackReplyMustEchoTheRequest() {
    const QByteArray reply = hex("3A04 0003 07 01 000A 0014");
    QCOMPARE(decodeReadTrackReply(reply, 4, 7).error().kind, ErrorKind::Communication);
    QCOMPARE(decodeReadTrackReply(reply, 3, 8).error().kind, ErrorKind::Communication);
    QCOMPARE(decodeReadTrackReply(hex("3A04 0003 07 02 000A 0014"), 3, 7).error().kind,
             ErrorKind::Communication);
    QCOMPARE(decodeReadTrackReply(hex("3A04 0003 07"), 3, 7).error().kind,
             ErrorKind::Communication);
    QList<Cam> fifteen;
    for (int i = 0; i < 15; ++i) fifteen.append({i, i + 1});
    QCOMPARE(encodeReadTrackReply(0, {1, fifteen}).error().kind, ErrorKind::Usage);
}

void TestShortCommands::decodesDeadTimeReply() {
    const Result<ShortDeadTime> deadTime = decodeReadDeadTimeReply(hex("3A06 05 00 04D2"), 5);
    QVERIFY(deadTime.ok());
    QCOMPARE(deadTime->output, 5);
    QCOMPARE(deadTime->deadTime, 1234);
    QCOMPARE(encodeReadDeadTimeReply({5, 1234}), hex("3A06 05 00 04D2"));
    QCOMPARE(decodeReadDeadTimeReply(hex("3A06 06 00 04D2"), 5).error().kind,
             ErrorKind::Communication);
    QCOMPARE(decodeReadDeadTimeReply(hex("3A06 05 00 04"), 5).error().kind,
             ErrorKind::Communication);
}

void TestShortCommands::tellsShortCommandsFromRk512() {
    QVERIFY(isShortCommandTelegram("?\x01"));
    QVERIFY(isShortCommandTelegram("!\x02"));
    QVERIFY(isShortCommandTelegram(":Z"));
    QVERIFY(!isShortCommandTelegram(hex("00004544050A0007FFFF")));
    QVERIFY(!isShortCommandTelegram({}));
}

void TestShortCommands::positionsAreSigned16Bit() {
    QVERIFY(kShortPositionsSigned);
    QCOMPARE(shortPositionValue(0xFFFF), -1);
    QCOMPARE(shortPositionValue(0x7FFF), 32767);
    QCOMPARE(shortPositionValue(0x8000), -32768);
    QCOMPARE(*shortPositionWord(-1, "x"), quint16(0xFFFF));
    QCOMPARE(shortPositionWord(32768, "x").error().kind, ErrorKind::Usage);
    QCOMPARE(shortPositionWord(-32769, "x").error().kind, ErrorKind::Usage);
}

QTEST_GUILESS_MAIN(TestShortCommands)
#include "tst_short_commands.moc"
