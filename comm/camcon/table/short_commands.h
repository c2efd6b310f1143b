#pragma once

#include "model/camcon/cam_program.h"
#include "model/result.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QList>

namespace cambench::comm::table {

// The short binary commands 0x01..0x07 (S7-CP340 coupling manual 4 and
// 5.1-5.7), which travel in 3964R telegrams like RK512 does. A telegram is
// a lead ('?' query, '!' command, ':' reply), the command number and the
// data: big-endian 16-bit words and single bytes, outputs numbered from 1.
//
// The manual's first data word, "length of the send data / destination
// number (always 0)", is the S7 mailbox's bookkeeping for its send block and
// is not on the line: RK512 telegrams, described with the same word, start
// with their 00 00 on the line (notes 7), and the S5-L1 forms of these
// commands start with the lead too (data-protocols manual 6).

enum class ShortCommand : quint8 {
    Status = 0x01,         // ? status, with virtual inputs
    ErrorReset = 0x02,     // ! reset "Ist-Err" / "Aus-Err"
    ProgramChange = 0x03,  // ! change the active program
    ReadTrack = 0x04,      // ? the cams of one output
    WriteTracks = 0x05,    // ! replace the cams of one or more outputs
    ReadDeadTime = 0x06,   // ? the dead time of one output
    WriteDeadTime = 0x07,  // ! the dead time of one output
};

inline constexpr char kShortQueryLead = '?';
inline constexpr char kShortCommandLead = '!';
inline constexpr char kShortReplyLead = ':';
inline constexpr char kShortUnknownMark = 'Z';  // ":Z" = query or command unknown (manual 4.3)
// Lead, number and at most 62 data bytes (manual 4.1).
inline constexpr int kMaxShortTelegramBytes = 64;

// Provisional: the manual does not say whether the 16-bit actual value,
// speed and cam points are signed. Read as two's complement, since a linear
// axis may start below zero; the one place to change if a device says
// otherwise. Program numbers and dead times are unsigned.
inline constexpr bool kShortPositionsSigned = true;
// The value of a 16-bit position word, and the word for a position (a
// usage error when it does not fit; `what` names the value in the message).
qint32 shortPositionValue(quint16 word);
Result<quint16> shortPositionWord(qint32 value, const QString& what);

// Whether `telegram` is a short command (lead '?', '!' or ':') rather than
// an RK512 telegram (00 00): both share one 3964R line.
bool isShortCommandTelegram(QByteArrayView telegram);

// --- PC side: requests ---------------------------------------------------

// `virtualInputs` (V1, V2, ... in whole 16-bit words, bit 0 of the first
// byte = V1) go with the query. Careful: without the PLC logic module the
// device ANDs these bits with its outputs, so zeros switch outputs off.
// None at all leaves the outputs alone.
Result<QByteArray> encodeStatusRequest(const QList<bool>& virtualInputs = {});
QByteArray encodeErrorResetRequest();
Result<QByteArray> encodeProgramChangeRequest(int program);
Result<QByteArray> encodeReadTrackRequest(int program, int output);
// Replaces every cam of each track's output in `program` (at most 14 cams
// in all, since the telegram holds 62 data bytes).
Result<QByteArray> encodeWriteTracksRequest(int program, const QList<Track>& tracks);
Result<QByteArray> encodeReadDeadTimeRequest(int output);
Result<QByteArray> encodeWriteDeadTimeRequest(int output, int deadTime);

// --- PC side: replies ----------------------------------------------------

struct ShortStatus {
    qint32 actualValue = 0;
    qint32 speed = 0;
    int program = 0;
    int deviceStatus = 0;  // 0 OK, 1..3 actual-value error 1..3, 4 output error
    int outputCount = 0;
    QList<bool> outputs;  // outputs[0] = output 1; outputCount entries
    friend bool operator==(const ShortStatus& a, const ShortStatus& b) {
        return a.actualValue == b.actualValue && a.speed == b.speed && a.program == b.program &&
               a.deviceStatus == b.deviceStatus && a.outputCount == b.outputCount &&
               a.outputs == b.outputs;
    }
};
// "OK", "actual-value error 2", ... for a status byte.
QString shortDeviceStatusText(int deviceStatus);

struct ShortDeadTime {
    int output = 1;
    int deadTime = 0;  // 0.1 ms
};

// Each decoder checks the lead and the command number, and turns ":Z" into a
// NotUnderstood error and "ER" into a DeviceError that says what to check.
Result<ShortStatus> decodeStatusReply(QByteArrayView reply);
// For 0x02, 0x03, 0x05, 0x07: "OK" or the error. The manual prints the
// reply to 0x07 with the number 0x05 (notes 10: a typo); 0x05 is accepted
// as well, since only one request is ever outstanding.
Status decodeAcknowledgement(ShortCommand command, QByteArrayView reply);
// The track of `output` in `program`, which the reply must echo.
Result<Track> decodeReadTrackReply(QByteArrayView reply, int program, int output);
Result<ShortDeadTime> decodeReadDeadTimeReply(QByteArrayView reply, int output);

// --- Device side: replies (simulator, tests) -----------------------------

QByteArray encodeAcknowledgement(ShortCommand command, bool ok);
QByteArray encodeUnknownCommandReply();
Result<QByteArray> encodeStatusReply(const ShortStatus& status);
Result<QByteArray> encodeReadTrackReply(int program, const Track& track);
QByteArray encodeReadDeadTimeReply(const ShortDeadTime& deadTime);

}  // namespace cambench::comm::table
