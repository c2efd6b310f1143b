#include "short_commands.h"

#include <QCoreApplication>

namespace cambench::comm::table {

namespace {

constexpr int kReplyHeaderBytes = 2;  // ':' + number

void appendWord(QByteArray& telegram, quint16 word) {
    telegram.append(char(word >> 8));
    telegram.append(char(word & 0xFF));
}

quint16 wordAt(QByteArrayView bytes, qsizetype index) {
    return quint16((quint8(bytes[index]) << 8) | quint8(bytes[index + 1]));
}

QByteArray start(char lead, ShortCommand command) {
    QByteArray telegram;
    telegram.append(lead);
    telegram.append(char(command));
    return telegram;
}

QString commandName(ShortCommand command) {
    switch (command) {
        case ShortCommand::Status:
            return QCoreApplication::translate("cambench::comm", "status query 0x01");
        case ShortCommand::ErrorReset:
            return QCoreApplication::translate("cambench::comm", "error reset 0x02");
        case ShortCommand::ProgramChange:
            return QCoreApplication::translate("cambench::comm", "program change 0x03");
        case ShortCommand::ReadTrack:
            return QCoreApplication::translate("cambench::comm", "track read 0x04");
        case ShortCommand::WriteTracks:
            return QCoreApplication::translate("cambench::comm", "track write 0x05");
        case ShortCommand::ReadDeadTime:
            return QCoreApplication::translate("cambench::comm", "dead-time read 0x06");
        case ShortCommand::WriteDeadTime:
            return QCoreApplication::translate("cambench::comm", "dead-time write 0x07");
    }
    return QCoreApplication::translate("cambench::comm", "short command 0x%1")
        .arg(quint8(command), 2, 16, QLatin1Char('0'));
}

// What to check when the device answers "ER".
QString refusalAdvice(ShortCommand command) {
    switch (command) {
        case ShortCommand::ErrorReset:
            return QCoreApplication::translate(
                "cambench::comm",
                "The cause of the error is still present; check the encoder and "
                "the outputs, then reset again.");
        case ShortCommand::ProgramChange:
            return QCoreApplication::translate(
                "cambench::comm", "Check that the program number is within the device's range.");
        case ShortCommand::WriteTracks:
            return QCoreApplication::translate(
                "cambench::comm",
                "Check the program and output numbers, that the cams lie "
                "between the smallest and largest actual value, and that the "
                "device has room for them.");
        case ShortCommand::WriteDeadTime:
            return QCoreApplication::translate(
                "cambench::comm",
                "Check the output number and that the dead time does not exceed "
                "the device's largest dead time.");
        default:
            return QString();
    }
}

Result<int> checkedByte(int value, int low, const QString& what) {
    if (value < low || value > 255) {
        return Error::usage(
            QCoreApplication::translate(
                "cambench::comm", "%1 %2 does not fit the byte of the short command (%3..255).")
                .arg(what)
                .arg(value)
                .arg(low));
    }
    return value;
}

Result<quint16> checkedUnsignedWord(int value, const QString& what) {
    if (value < 0 || value > 0xFFFF) {
        return Error::usage(
            QCoreApplication::translate(
                "cambench::comm",
                "%1 %2 does not fit the 16-bit word of the short command (0..65535).")
                .arg(what)
                .arg(value));
    }
    return quint16(value);
}

// Checks lead and number of a reply; nullopt when they fit.
std::optional<Error> checkReplyHead(QByteArrayView reply, ShortCommand command,
                                    std::optional<ShortCommand> alsoAccepted = std::nullopt) {
    if (reply.size() >= 2 && reply[0] == kShortReplyLead && reply[1] == kShortUnknownMark) {
        return Error{
            ErrorKind::NotUnderstood,
            QCoreApplication::translate("cambench::comm",
                                        "The device does not know the %1 (it answered \":Z\"); its "
                                        "firmware may not have it. Use the table interface (RK512) "
                                        "instead.")
                .arg(commandName(command)),
            0};
    }
    const bool numberFits =
        reply.size() >= 2 && (quint8(reply[1]) == quint8(command) ||
                              (alsoAccepted && quint8(reply[1]) == quint8(*alsoAccepted)));
    if (reply.size() < kReplyHeaderBytes || reply[0] != kShortReplyLead || !numberFits) {
        return Error::communication(
            QCoreApplication::translate(
                "cambench::comm",
                "The reply to the %1 does not start with ':' and its number (got %2). "
                "Check that the device's serial mode is 3964R.")
                .arg(commandName(command),
                     QString::fromLatin1(
                         reply.first(qMin<qsizetype>(reply.size(), 8)).toByteArray().toHex(' '))));
    }
    return std::nullopt;
}

Error wrongLength(ShortCommand command, qsizetype got, const QString& expected) {
    return Error::communication(
        QCoreApplication::translate("cambench::comm",
                                    "The reply to the %1 has %2 bytes, %3 expected.")
            .arg(commandName(command))
            .arg(got)
            .arg(expected));
}

}  // namespace

qint32 shortPositionValue(quint16 word) {
    if (kShortPositionsSigned) return qint16(word);
    return word;
}

Result<quint16> shortPositionWord(qint32 value, const QString& what) {
    const qint32 low = kShortPositionsSigned ? -32768 : 0;
    const qint32 high = kShortPositionsSigned ? 32767 : 65535;
    if (value < low || value > high) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "%1 %2 does not fit the 16-bit word of the short "
                                        "commands (%3..%4); use the table interface (RK512).")
                .arg(what)
                .arg(value)
                .arg(low)
                .arg(high));
    }
    return quint16(value);
}

bool isShortCommandTelegram(QByteArrayView telegram) {
    if (telegram.isEmpty()) return false;
    const char lead = telegram[0];
    return lead == kShortQueryLead || lead == kShortCommandLead || lead == kShortReplyLead;
}

Result<QByteArray> encodeStatusRequest(const QList<bool>& virtualInputs) {
    if (virtualInputs.size() % 16 != 0) {
        return Error::usage(
            QCoreApplication::translate(
                "cambench::comm",
                "Virtual inputs go in whole 16-bit words; give a multiple of 16 (got %1). Choose "
                "the "
                "extra bits with care: without the PLC logic module a 0 switches its output off.")
                .arg(virtualInputs.size()));
    }
    QByteArray telegram = start(kShortQueryLead, ShortCommand::Status);
    QByteArray bits(virtualInputs.size() / 8, '\0');
    for (qsizetype i = 0; i < virtualInputs.size(); ++i) {
        if (virtualInputs[i]) bits[i / 8] = char(quint8(bits[i / 8]) | (1u << (i % 8)));
    }
    telegram.append(bits);
    if (telegram.size() > kMaxShortTelegramBytes) {
        return Error::usage(
            QCoreApplication::translate(
                "cambench::comm", "%1 virtual inputs do not fit one status query (at most %2).")
                .arg(virtualInputs.size())
                .arg((kMaxShortTelegramBytes - 2) * 8));
    }
    return telegram;
}

QByteArray encodeErrorResetRequest() {
    return start(kShortCommandLead, ShortCommand::ErrorReset);
}

Result<QByteArray> encodeProgramChangeRequest(int program) {
    const Result<quint16> word =
        checkedUnsignedWord(program, QCoreApplication::translate("cambench::comm", "Program"));
    if (!word) return word.error();
    QByteArray telegram = start(kShortCommandLead, ShortCommand::ProgramChange);
    appendWord(telegram, *word);
    return telegram;
}

Result<QByteArray> encodeReadTrackRequest(int program, int output) {
    const Result<quint16> programWord =
        checkedUnsignedWord(program, QCoreApplication::translate("cambench::comm", "Program"));
    if (!programWord) return programWord.error();
    const Result<int> outputByte =
        checkedByte(output, 1, QCoreApplication::translate("cambench::comm", "Output"));
    if (!outputByte) return outputByte.error();
    QByteArray telegram = start(kShortQueryLead, ShortCommand::ReadTrack);
    appendWord(telegram, *programWord);
    telegram.append(char(*outputByte));
    telegram.append('\0');  // free byte
    return telegram;
}

Result<QByteArray> encodeWriteTracksRequest(int program, const QList<Track>& tracks) {
    const Result<quint16> programWord =
        checkedUnsignedWord(program, QCoreApplication::translate("cambench::comm", "Program"));
    if (!programWord) return programWord.error();
    QByteArray telegram = start(kShortCommandLead, ShortCommand::WriteTracks);
    appendWord(telegram, *programWord);
    for (const Track& track : tracks) {
        const Result<int> outputByte =
            checkedByte(track.output, 1, QCoreApplication::translate("cambench::comm", "Output"));
        if (!outputByte) return outputByte.error();
        const Result<int> countByte = checkedByte(
            int(track.cams.size()), 0, QCoreApplication::translate("cambench::comm", "Cam count"));
        if (!countByte) return countByte.error();
        telegram.append(char(*outputByte));
        telegram.append(char(*countByte));
        for (qsizetype i = 0; i < track.cams.size(); ++i) {
            const Result<quint16> on = shortPositionWord(
                track.cams[i].on,
                QCoreApplication::translate("cambench::comm", "Output %1, cam %2: switch-on point")
                    .arg(track.output)
                    .arg(i + 1));
            if (!on) return on.error();
            const Result<quint16> off = shortPositionWord(
                track.cams[i].off,
                QCoreApplication::translate("cambench::comm", "Output %1, cam %2: switch-off point")
                    .arg(track.output)
                    .arg(i + 1));
            if (!off) return off.error();
            appendWord(telegram, *on);
            appendWord(telegram, *off);
        }
    }
    appendWord(telegram, 0xFFFF);  // end mark
    if (telegram.size() > kMaxShortTelegramBytes) {
        return Error::usage(
            QCoreApplication::translate(
                "cambench::comm",
                "The track write needs %1 bytes; a short command holds %2 (about 14 "
                "cams in all). Write fewer tracks per command, or use the table "
                "interface (RK512) for longer tracks.")
                .arg(telegram.size())
                .arg(kMaxShortTelegramBytes));
    }
    return telegram;
}

Result<QByteArray> encodeReadDeadTimeRequest(int output) {
    const Result<int> outputByte =
        checkedByte(output, 1, QCoreApplication::translate("cambench::comm", "Output"));
    if (!outputByte) return outputByte.error();
    QByteArray telegram = start(kShortQueryLead, ShortCommand::ReadDeadTime);
    telegram.append(char(*outputByte));
    telegram.append('\0');  // free byte
    return telegram;
}

Result<QByteArray> encodeWriteDeadTimeRequest(int output, int deadTime) {
    const Result<int> outputByte =
        checkedByte(output, 1, QCoreApplication::translate("cambench::comm", "Output"));
    if (!outputByte) return outputByte.error();
    const Result<quint16> deadTimeWord = checkedUnsignedWord(
        deadTime, QCoreApplication::translate("cambench::comm", "Dead time (0.1 ms)"));
    if (!deadTimeWord) return deadTimeWord.error();
    QByteArray telegram = start(kShortCommandLead, ShortCommand::WriteDeadTime);
    telegram.append(char(*outputByte));
    telegram.append('\0');  // free byte
    appendWord(telegram, *deadTimeWord);
    return telegram;
}

QString shortDeviceStatusText(int deviceStatus) {
    switch (deviceStatus) {
        case 0:
            return QStringLiteral("OK");
        case 1:
        case 2:
        case 3:
            return QCoreApplication::translate("cambench::comm", "actual-value error %1")
                .arg(deviceStatus);
        case 4:
            return QCoreApplication::translate("cambench::comm", "output error");
        default:
            return QCoreApplication::translate("cambench::comm", "unknown status %1")
                .arg(deviceStatus);
    }
}

Result<ShortStatus> decodeStatusReply(QByteArrayView reply) {
    constexpr ShortCommand command = ShortCommand::Status;
    if (std::optional<Error> error = checkReplyHead(reply, command)) return *error;
    // actual value, speed, program (words), status, output count (bytes)
    constexpr int kFixedBytes = kReplyHeaderBytes + 8;
    if (reply.size() < kFixedBytes) {
        return wrongLength(
            command, reply.size(),
            QCoreApplication::translate("cambench::comm", "at least %1").arg(kFixedBytes));
    }
    ShortStatus status;
    status.actualValue = shortPositionValue(wordAt(reply, 2));
    status.speed = shortPositionValue(wordAt(reply, 4));
    status.program = wordAt(reply, 6);
    status.deviceStatus = quint8(reply[8]);
    status.outputCount = quint8(reply[9]);
    const QByteArrayView bits = reply.sliced(kFixedBytes);
    if (bits.size() * 8 < status.outputCount) {
        return wrongLength(command, reply.size(),
                           QCoreApplication::translate("cambench::comm", "%1 for %2 outputs")
                               .arg(kFixedBytes + (status.outputCount + 7) / 8)
                               .arg(status.outputCount));
    }
    for (int i = 0; i < status.outputCount; ++i) {
        status.outputs.append((quint8(bits[i / 8]) >> (i % 8)) & 1);
    }
    return status;
}

Status decodeAcknowledgement(ShortCommand command, QByteArrayView reply) {
    // Notes 10: the manual prints 0x05 in the reply to 0x07.
    const std::optional<ShortCommand> typo = command == ShortCommand::WriteDeadTime
                                                 ? std::optional(ShortCommand::WriteTracks)
                                                 : std::nullopt;
    if (std::optional<Error> error = checkReplyHead(reply, command, typo)) return *error;
    const QByteArrayView answer = reply.sliced(kReplyHeaderBytes);
    if (answer == QByteArrayView("OK")) return success();
    if (answer == QByteArrayView("ER")) {
        return Error::device(
            0, QCoreApplication::translate("cambench::comm",
                                           "The device refused the %1 (it answered \"ER\"). %2")
                   .arg(commandName(command), refusalAdvice(command)));
    }
    return Error::communication(
        QCoreApplication::translate("cambench::comm",
                                    "The reply to the %1 is neither \"OK\" nor \"ER\" (got %2).")
            .arg(commandName(command), QString::fromLatin1(answer.toByteArray().toHex(' '))));
}

Result<Track> decodeReadTrackReply(QByteArrayView reply, int program, int output) {
    constexpr ShortCommand command = ShortCommand::ReadTrack;
    if (std::optional<Error> error = checkReplyHead(reply, command)) return *error;
    constexpr int kFixedBytes = kReplyHeaderBytes + 4;  // program word, output, cam count
    if (reply.size() < kFixedBytes) {
        return wrongLength(
            command, reply.size(),
            QCoreApplication::translate("cambench::comm", "at least %1").arg(kFixedBytes));
    }
    const int echoedProgram = wordAt(reply, 2);
    const int echoedOutput = quint8(reply[4]);
    const int count = quint8(reply[5]);
    if (echoedProgram != program || echoedOutput != output) {
        return Error::communication(
            QCoreApplication::translate(
                "cambench::comm",
                "Asked for program %1, output %2; the reply is for program %3, output "
                "%4. Read the track again.")
                .arg(program)
                .arg(output)
                .arg(echoedProgram)
                .arg(echoedOutput));
    }
    if (reply.size() != kFixedBytes + 4 * count) {
        return wrongLength(command, reply.size(),
                           QCoreApplication::translate("cambench::comm", "%1 for %2 cams")
                               .arg(kFixedBytes + 4 * count)
                               .arg(count));
    }
    Track track;
    track.output = output;
    for (int i = 0; i < count; ++i) {
        const qsizetype at = kFixedBytes + 4 * i;
        track.cams.append(
            Cam{shortPositionValue(wordAt(reply, at)), shortPositionValue(wordAt(reply, at + 2))});
    }
    return track;
}

Result<ShortDeadTime> decodeReadDeadTimeReply(QByteArrayView reply, int output) {
    constexpr ShortCommand command = ShortCommand::ReadDeadTime;
    if (std::optional<Error> error = checkReplyHead(reply, command)) return *error;
    constexpr int kBytes = kReplyHeaderBytes + 4;  // output, free byte, dead time word
    if (reply.size() != kBytes) {
        return wrongLength(command, reply.size(), QString::number(kBytes));
    }
    const int echoedOutput = quint8(reply[2]);
    if (echoedOutput != output) {
        return Error::communication(
            QCoreApplication::translate(
                "cambench::comm",
                "Asked for the dead time of output %1; the reply is for output %2. "
                "Read it again.")
                .arg(output)
                .arg(echoedOutput));
    }
    return ShortDeadTime{output, wordAt(reply, 4)};
}

QByteArray encodeAcknowledgement(ShortCommand command, bool ok) {
    QByteArray telegram = start(kShortReplyLead, command);
    telegram.append(ok ? "OK" : "ER");
    return telegram;
}

QByteArray encodeUnknownCommandReply() {
    QByteArray telegram;
    telegram.append(kShortReplyLead);
    telegram.append(kShortUnknownMark);
    return telegram;
}

Result<QByteArray> encodeStatusReply(const ShortStatus& status) {
    QByteArray telegram = start(kShortReplyLead, ShortCommand::Status);
    const Result<quint16> actual = shortPositionWord(
        status.actualValue, QCoreApplication::translate("cambench::comm", "Actual value"));
    if (!actual) return actual.error();
    const Result<quint16> speed =
        shortPositionWord(status.speed, QCoreApplication::translate("cambench::comm", "Speed"));
    if (!speed) return speed.error();
    const Result<quint16> program = checkedUnsignedWord(
        status.program, QCoreApplication::translate("cambench::comm", "Program"));
    if (!program) return program.error();
    const Result<int> count = checkedByte(
        status.outputCount, 0, QCoreApplication::translate("cambench::comm", "Output count"));
    if (!count) return count.error();
    appendWord(telegram, *actual);
    appendWord(telegram, *speed);
    appendWord(telegram, *program);
    telegram.append(char(status.deviceStatus));
    telegram.append(char(*count));
    // Whole 16-bit words of output bits (manual 5.1).
    QByteArray bits(((*count + 15) / 16) * 2, '\0');
    for (int i = 0; i < *count && i < status.outputs.size(); ++i) {
        if (status.outputs[i]) bits[i / 8] = char(quint8(bits[i / 8]) | (1u << (i % 8)));
    }
    telegram.append(bits);
    if (telegram.size() > kMaxShortTelegramBytes) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm", "%1 outputs do not fit one status reply.")
                .arg(*count));
    }
    return telegram;
}

Result<QByteArray> encodeReadTrackReply(int program, const Track& track) {
    const Result<quint16> programWord =
        checkedUnsignedWord(program, QCoreApplication::translate("cambench::comm", "Program"));
    if (!programWord) return programWord.error();
    const Result<int> outputByte =
        checkedByte(track.output, 1, QCoreApplication::translate("cambench::comm", "Output"));
    if (!outputByte) return outputByte.error();
    const Result<int> countByte = checkedByte(
        int(track.cams.size()), 0, QCoreApplication::translate("cambench::comm", "Cam count"));
    if (!countByte) return countByte.error();
    QByteArray telegram = start(kShortReplyLead, ShortCommand::ReadTrack);
    appendWord(telegram, *programWord);
    telegram.append(char(*outputByte));
    telegram.append(char(*countByte));
    for (const Cam& cam : track.cams) {
        const Result<quint16> on = shortPositionWord(
            cam.on, QCoreApplication::translate("cambench::comm", "Switch-on point"));
        if (!on) return on.error();
        const Result<quint16> off = shortPositionWord(
            cam.off, QCoreApplication::translate("cambench::comm", "Switch-off point"));
        if (!off) return off.error();
        appendWord(telegram, *on);
        appendWord(telegram, *off);
    }
    if (telegram.size() > kMaxShortTelegramBytes) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "%1 cams do not fit one track reply (at most 14).")
                .arg(track.cams.size()));
    }
    return telegram;
}

QByteArray encodeReadDeadTimeReply(const ShortDeadTime& deadTime) {
    QByteArray telegram = start(kShortReplyLead, ShortCommand::ReadDeadTime);
    telegram.append(char(deadTime.output));
    telegram.append('\0');  // free byte
    appendWord(telegram, quint16(deadTime.deadTime));
    return telegram;
}

}  // namespace cambench::comm::table
