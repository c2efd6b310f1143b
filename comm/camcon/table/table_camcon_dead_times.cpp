// Dead times of areas 1..200: word 0 (mode Normal) and words 251..253.
#include "table_camcon.h"
#include "table_map.h"

#include "comm/device/error_context.h"

#include <QCoreApplication>

namespace cambench::comm::table {

Result<DeadTimes> TableCamCon::readDeadTimes(int outputs) {
    DeadTimes deadTimes;
    for (int output = 1; output <= outputs; ++output) {
        const Result<int> area = trackArea(output);
        if (!area) return area.error();
        const Result<qint32> value = m_link.readWord(*area, tableWord(u"track.dead_time"));
        if (!value)
            return inContext(
                QCoreApplication::translate("cambench::comm", "reading the dead time of output %1")
                    .arg(output),
                value.error());
        deadTimes.insert(output, *value);
    }
    return deadTimes;
}

Status TableCamCon::writeDeadTime(int output, qint32 tenthsMs) {
    const QString what =
        QCoreApplication::translate("cambench::comm", "writing the dead time of output %1")
            .arg(output);
    const Result<int> area = trackArea(output);
    if (!area) return inContext(what, area.error());
    const Status written = m_link.writeWord(*area, tableWord(u"track.dead_time"), tenthsMs);
    if (!written) return inContext(what, written.error());
    return success();
}

Result<DeadTimeModes> TableCamCon::readDeadTimeModes(int outputs) {
    if (!has(CamConCapability::DeadTimeModes)) return missing(CamConCapability::DeadTimeModes);
    DeadTimeModes modes;
    for (int output = 1; output <= outputs; ++output) {
        const QString what =
            QCoreApplication::translate("cambench::comm", "reading the dead-time mode of output %1")
                .arg(output);
        const Result<int> area = trackArea(output);
        if (!area) return area.error();
        const Result<qint32> normal = m_link.readWord(*area, tableWord(u"track.dead_time"));
        if (!normal) return inContext(what, normal.error());
        const int first = tableWord(u"track.dead_time_mode");
        const Result<QList<qint32>> words =
            m_link.readWords(*area, first, tableWord(u"track.dead_time_off") - first + 1);
        if (!words) return inContext(what, words.error());
        const std::optional<DeadTimeMode> mode = deadTimeModeFromNumber(words->at(0));
        if (!mode) {
            return Error::communication(
                QCoreApplication::translate(
                    "cambench::comm",
                    "%1: the device reports mode %2, which the manual does not list "
                    "(0, 1, 2); check the device")
                    .arg(what)
                    .arg(words->at(0)));
        }
        modes.insert(output, OutputDeadTime{*mode, *normal, words->at(1), words->at(2)});
    }
    return modes;
}

Status TableCamCon::writeDeadTimeMode(int output, const OutputDeadTime& deadTime) {
    if (!has(CamConCapability::DeadTimeModes)) return missing(CamConCapability::DeadTimeModes);
    const QString what =
        QCoreApplication::translate("cambench::comm", "writing the dead-time mode of output %1")
            .arg(output);
    const Result<int> area = trackArea(output);
    if (!area) return inContext(what, area.error());
    const Status normal = m_link.writeWord(*area, tableWord(u"track.dead_time"), deadTime.normal);
    if (!normal) return inContext(what, normal.error());
    // Mode and both values in one telegram: never a new mode with old values.
    const Status written = m_link.writeWords(*area, tableWord(u"track.dead_time_mode"),
                                             {qint32(deadTime.mode), deadTime.on, deadTime.off});
    if (!written) return inContext(what, written.error());
    return success();
}

}  // namespace cambench::comm::table
