// The short commands 0x01..0x07 (S7-CP340 coupling manual 5.1 - 5.7) on the
// simulated device: requests parsed here, replies encoded by
// comm/camcon/table/short_commands.h. Outputs count from 1 on the line.
#include "sim_table_device.h"

#include "comm/camcon/table/short_commands.h"
#include "comm/sim/camcon/sim_device.h"
#include "comm/sim/sim_log.h"

namespace cambench::comm {

using table::ShortCommand;

namespace {

constexpr quint16 kEndMark = 0xFFFF;

quint16 wordAt(const QByteArray& bytes, qsizetype at) {
    return quint16((quint8(bytes.at(at)) << 8) | quint8(bytes.at(at + 1)));
}

bool validOutput(const SimDevice& device, int output) {
    return output >= 1 && output <= device.profile().outputs;
}

QByteArray status(SimDevice& device, const QByteArray& telegram) {
    // Virtual inputs may follow (whole 16-bit words, bit 0 = V1).
    if (telegram.size() > 2) device.runtime().vInputs = telegram.mid(2);
    table::ShortStatus status;
    // The 16-bit words carry the low bits of larger values, as a real
    // device's would (provisional: the manual gives no range).
    status.actualValue = table::shortPositionValue(quint16(device.axis().position()));
    status.speed = table::shortPositionValue(quint16(qint32(device.axis().unitsPerSecond())));
    status.program = device.state().activeProgram;
    status.deviceStatus = device.runtime().errorState;
    status.outputCount = device.profile().outputs;
    for (int output = 0; output < status.outputCount; ++output) {
        status.outputs.append(
            device.axis().running() &&
            device.state().cams.isOn(status.program, output, device.axis().position()));
    }
    const Result<QByteArray> reply = table::encodeStatusReply(status);
    return reply ? *reply : table::encodeAcknowledgement(ShortCommand::Status, false);
}

bool programChange(SimDevice& device, const QByteArray& telegram) {
    if (telegram.size() != 4) return false;
    const std::optional<SimResult> result =
        device.call(kCommand, "PAU", Fields().set("value", wordAt(telegram, 2)));
    return result && result->kind != SimResult::Error;
}

QByteArray readTrack(SimDevice& device, const QByteArray& telegram) {
    const auto refuse = table::encodeAcknowledgement(ShortCommand::ReadTrack, false);
    if (telegram.size() != 6) return refuse;
    const int program = wordAt(telegram, 2);
    const int output = quint8(telegram.at(4));
    if (program >= device.profile().programs || !validOutput(device, output)) return refuse;
    const Track track{output, device.state().cams.track(program, output - 1)};
    const Result<QByteArray> reply = table::encodeReadTrackReply(program, track);
    return reply ? *reply : refuse;
}

// Replaces the cams of every output listed; nothing changes unless all fit.
bool writeTracks(SimDevice& device, const QByteArray& telegram) {
    if (telegram.size() < 6) return false;
    const int program = wordAt(telegram, 2);
    if (program >= device.profile().programs) return false;
    SimCamStore store = device.state().cams;
    qsizetype at = 4;
    while (at + 2 <= telegram.size() && wordAt(telegram, at) != kEndMark) {
        const int output = quint8(telegram.at(at));
        const int count = quint8(telegram.at(at + 1));
        at += 2;
        if (!validOutput(device, output) || at + 4 * count > telegram.size()) return false;
        QList<Cam> cams;
        for (int i = 0; i < count; ++i, at += 4) {
            cams.append({table::shortPositionValue(wordAt(telegram, at)),
                         table::shortPositionValue(wordAt(telegram, at + 2))});
        }
        if (store.replaceTrack(program, output - 1, cams) != 0) return false;
    }
    if (at + 2 != telegram.size()) return false;  // no end mark, or bytes after it
    device.state().cams = store;
    return true;
}

QByteArray readDeadTime(SimDevice& device, const QByteArray& telegram) {
    const int output = telegram.size() == 4 ? quint8(telegram.at(2)) : 0;
    if (!validOutput(device, output))
        return table::encodeAcknowledgement(ShortCommand::ReadDeadTime, false);
    return table::encodeReadDeadTimeReply({output, device.state().deadTimes.value(output - 1)});
}

bool writeDeadTime(SimDevice& device, const QByteArray& telegram) {
    if (telegram.size() != 6) return false;
    const std::optional<SimResult> result = device.call(
        kCommand, "TZK",
        Fields().set("output", quint8(telegram.at(2)) - 1).set("value", wordAt(telegram, 4)));
    return result && result->kind != SimResult::Error;
}

}  // namespace

QByteArray SimTableDevice::executeShort(const QByteArray& telegram) {
    if (telegram.size() < 2) return table::encodeUnknownCommandReply();
    const char lead = telegram.at(0);
    const auto command = ShortCommand(quint8(telegram.at(1)));
    qCDebug(commSimLog) << "short command" << lead << quint8(telegram.at(1));
    const bool query = lead == table::kShortQueryLead;
    const bool order = lead == table::kShortCommandLead;
    switch (command) {
        case ShortCommand::Status:
            if (query) return status(m_device, telegram);
            break;
        case ShortCommand::ErrorReset:
            if (order && telegram.size() == 2) {
                m_device.runtime().errorState = 0;
                return table::encodeAcknowledgement(command, true);
            }
            break;
        case ShortCommand::ProgramChange:
            if (order)
                return table::encodeAcknowledgement(command, programChange(m_device, telegram));
            break;
        case ShortCommand::ReadTrack:
            if (query) return readTrack(m_device, telegram);
            break;
        case ShortCommand::WriteTracks:
            if (order)
                return table::encodeAcknowledgement(command, writeTracks(m_device, telegram));
            break;
        case ShortCommand::ReadDeadTime:
            if (query) return readDeadTime(m_device, telegram);
            break;
        case ShortCommand::WriteDeadTime:
            if (order)
                return table::encodeAcknowledgement(command, writeDeadTime(m_device, telegram));
            break;
    }
    return table::encodeUnknownCommandReply();
}

}  // namespace cambench::comm
