#include "short_client.h"

#include "table_link.h"

#include "comm/device/error_context.h"

#include <QCoreApplication>

namespace cambench::comm::table {

Result<QByteArray> ShortClient::exchange(const Result<QByteArray>& request, const QString& what) {
    if (!request) return inContext(what, request.error());
    const Result<QByteArray> reply =
        m_link.shortCommand(*request, what, kMaxShortTelegramBytes, RetryPolicy::Idempotent);
    if (!reply) return inContext(what, reply.error());
    return reply;
}

Status ShortClient::acknowledged(ShortCommand command, const Result<QByteArray>& request,
                                 const QString& what) {
    const Result<QByteArray> reply = exchange(request, what);
    if (!reply) return reply.error();
    const Status ok = decodeAcknowledgement(command, *reply);
    if (!ok) return inContext(what, ok.error());
    return success();
}

Result<ShortStatus> ShortClient::status() {
    const QString what = QCoreApplication::translate("cambench::comm", "reading the status (0x01)");
    const Result<QByteArray> reply = exchange(encodeStatusRequest(), what);
    if (!reply) return reply.error();
    const Result<ShortStatus> decoded = decodeStatusReply(*reply);
    if (!decoded) return inContext(what, decoded.error());
    return decoded;
}

Status ShortClient::resetErrors() {
    return acknowledged(
        ShortCommand::ErrorReset, encodeErrorResetRequest(),
        QCoreApplication::translate("cambench::comm", "resetting the error (0x02)"));
}

Status ShortClient::changeProgram(int program) {
    return acknowledged(
        ShortCommand::ProgramChange, encodeProgramChangeRequest(program),
        QCoreApplication::translate("cambench::comm", "selecting program %1 (0x03)").arg(program));
}

Result<Track> ShortClient::readTrack(int program, int output) {
    const QString what =
        QCoreApplication::translate("cambench::comm", "reading output %1 of program %2 (0x04)")
            .arg(output)
            .arg(program);
    const Result<QByteArray> reply = exchange(encodeReadTrackRequest(program, output), what);
    if (!reply) return reply.error();
    const Result<Track> track = decodeReadTrackReply(*reply, program, output);
    if (!track) return inContext(what, track.error());
    return track;
}

Status ShortClient::writeTrack(int program, const Track& track) {
    return acknowledged(
        ShortCommand::WriteTracks, encodeWriteTracksRequest(program, {track}),
        QCoreApplication::translate("cambench::comm", "writing output %1 of program %2 (0x05)")
            .arg(track.output)
            .arg(program));
}

Result<int> ShortClient::readDeadTime(int output) {
    const QString what =
        QCoreApplication::translate("cambench::comm", "reading the dead time of output %1 (0x06)")
            .arg(output);
    const Result<QByteArray> reply = exchange(encodeReadDeadTimeRequest(output), what);
    if (!reply) return reply.error();
    const Result<ShortDeadTime> deadTime = decodeReadDeadTimeReply(*reply, output);
    if (!deadTime) return inContext(what, deadTime.error());
    return deadTime->deadTime;
}

Status ShortClient::writeDeadTime(int output, int tenthsMs) {
    return acknowledged(
        ShortCommand::WriteDeadTime, encodeWriteDeadTimeRequest(output, tenthsMs),
        QCoreApplication::translate("cambench::comm", "writing the dead time of output %1 (0x07)")
            .arg(output));
}

Result<ShortClient*> shortCommandsOf(CamConDevice& device) {
    if (ShortClient* client = device.shortCommands()) return client;
    return device.missing(CamConCapability::ShortCommands);
}

}  // namespace cambench::comm::table
