#include "ascii_camcon.h"

#include <QCoreApplication>
#include "ascii_support.h"

namespace cambench::comm {

using namespace client;

namespace {

// One number of DeviceInfo and the query that reads it. Optional queries
// may be unknown to older firmware (:Z); the default value stays then.
struct InfoQuery {
    const char* command;
    int DeviceInfo::*member;
    bool optional;
};

const InfoQuery kInfoQueries[] = {
    {"GNR", &DeviceInfo::deviceNumber, true},
    {"GSIO", &DeviceInfo::protocol, true},
    {"AMAX", &DeviceInfo::outputs, false},
    {"EMAX", &DeviceInfo::inputs, false},
    {"GTZKANZ", &DeviceInfo::deadTimeOutputs, true},
    {"GPRGMAX", &DeviceInfo::programs, false},
    {"IMIN", &DeviceInfo::minPosition, false},
    {"IMAX", &DeviceInfo::maxPosition, false},
    {"GTZKMAX", &DeviceInfo::maxDeadTime, true},
    {"GCPUCLK", &DeviceInfo::cpuClock, true},
    {"GTEMP", &DeviceInfo::temperature, true},
    {"MEEFREE", &DeviceInfo::freeCams, true},
    {"MEENOCK", &DeviceInfo::programmedCams, true},
    {"MEETZK", &DeviceInfo::programmedDeadTimes, true},
    {"MRAMMAX", &DeviceInfo::ramSize, true},
    {"MRAMFREE", &DeviceInfo::ramFree, true},
    {"MEES", &DeviceInfo::serialEepromSize, true},
    {"MPEE", &DeviceInfo::parallelEepromSize, true},
};

// Bit n of a status table (bit 0 of the first byte = number 0).
QList<bool> bitsOf(const QByteArray& table, int count) {
    QList<bool> bits(count, false);
    for (int i = 0; i < count && i / 8 < table.size(); ++i) {
        bits[i] = (quint8(table.at(i / 8)) >> (i % 8)) & 1;
    }
    return bits;
}

}  // namespace

Result<DeviceInfo> AsciiCamCon::readInfo() {
    DeviceInfo info;
    const Result<Fields> eprom = m_link.call('?', "EPROM");
    if (!eprom)
        return inContext(
            QCoreApplication::translate("cambench::comm", "reading the device identity (?EPROM)"),
            eprom.error());
    info.epromDate = text(*eprom, "text");
    for (const InfoQuery& query : kInfoQueries) {
        const Result<Fields> reply = m_link.call('?', query.command);
        if (!reply) {
            if (query.optional && isNotUnderstood(reply.error())) continue;
            return inContext(
                QCoreApplication::translate("cambench::comm", "reading the device identity (?%1)")
                    .arg(QLatin1String(query.command)),
                reply.error());
        }
        info.*query.member = int(reply->num("value"));
    }
    return info;
}

Result<DeviceStatus> AsciiCamCon::readStatus(int outputs, int inputs) {
    DeviceStatus status;
    const Result<Fields> error = m_link.call('?', "ERR");
    if (!error)
        return inContext(
            QCoreApplication::translate("cambench::comm", "reading the error state (?ERR)"),
            error.error());
    status.errorState = int(error->num("value"));

    // The provisional queries (notes 3) may be unknown to the firmware.
    struct Optional {
        const char* command;
        std::function<void(const Fields&)> apply;
    };
    // The axis moves between replies: the output states are read right
    // after the position so that the two shown together belong together.
    const Optional queries[] = {
        {"IGWG", [&](const Fields& f) { status.position = qint32(f.num("value")); }},
        {"ATAB", [&](const Fields& f) { status.outputs = bitsOf(f.bytes("data"), outputs); }},
        {"IFGWG", [&](const Fields& f) { status.positionText = text(f, "text").trimmed(); }},
        {"BSPEED", [&](const Fields& f) { status.speed = qint32(f.num("value")); }},
        {"SPEED", [&](const Fields& f) { status.speedText = text(f, "text").trimmed(); }},
        {"PAU", [&](const Fields& f) { status.activeProgram = int(f.num("value")); }},
        {"ETAB", [&](const Fields& f) { status.inputs = bitsOf(f.bytes("data"), inputs); }},
    };
    for (const Optional& query : queries) {
        const Result<Fields> reply = m_link.call('?', query.command);
        if (reply) {
            query.apply(*reply);
        } else if (!isNotUnderstood(reply.error())) {
            return inContext(
                QCoreApplication::translate("cambench::comm", "reading the status (?%1)")
                    .arg(QLatin1String(query.command)),
                reply.error());
        }
    }
    return status;
}

Status AsciiCamCon::resetError() {
    const Result<Fields> reply = m_link.call('!', "ERR");
    if (!reply)
        return inContext(
            QCoreApplication::translate("cambench::comm", "resetting the error (!ERR)"),
            reply.error());
    return success();
}

Status AsciiCamCon::selectProgram(int program) {
    const Result<Fields> reply = m_link.call('!', "PAU", Fields{{"value", qint64(program)}});
    if (!reply) {
        return inContext(
            QCoreApplication::translate("cambench::comm", "selecting program %1 (!PAU)")
                .arg(program),
            reply.error());
    }
    return success();
}

}  // namespace cambench::comm
