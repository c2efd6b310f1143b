#include "table_camcon.h"

#include "table_map.h"
#include "table_protocol.h"

#include <QCoreApplication>

namespace cambench::comm::table {

namespace {

// The words a dead-time mode needs (251..253) lie beyond what e38 reaches.
bool reachesDeadTimeModes(const TableLink& link) {
    return link.reachableWords() > tableWord(u"track.dead_time_off");
}

}  // namespace

TableCamCon::TableCamCon(Transport& transport, const TableSettings& settings,
                         const LineTiming& line)
    : m_ownLink(std::make_unique<TableLink>(transport, settings, line)), m_link(*m_ownLink) {}

TableCamCon::TableCamCon(TableLink& link) : m_link(link) {}

TableCamCon::~TableCamCon() = default;

QString TableCamCon::protocolId() const {
    return tableProtocolId(m_link.variant());
}

bool TableCamCon::has(CamConCapability capability) const {
    switch (capability) {
        case CamConCapability::Users:
        case CamConCapability::EepromBackup:
        case CamConCapability::BusScan:
        case CamConCapability::Terminal:
        case CamConCapability::OutputNames:
            return false;
        case CamConCapability::DeadTimeModes:
            return reachesDeadTimeModes(m_link);
        case CamConCapability::PlcNetworks:
        case CamConCapability::AnalogueCams:
        case CamConCapability::EepromLock:
        case CamConCapability::ProgrammingProgram:
        case CamConCapability::ShortCommands:
            return true;
    }
    return false;
}

QString TableCamCon::lacks(CamConCapability capability) const {
    if (capability == CamConCapability::DeadTimeModes && !reachesDeadTimeModes(m_link)) {
        return QCoreApplication::translate(
            "cambench::comm",
            "Dead-time modes are data words 251..253, which 3964R e38 cannot "
            "address (words 0..127); set the device to 3964R n96 "
            "(--protocol 3964r-n96) to reach them.");
    }
    return CamConDevice::lacks(capability);
}

Result<int> TableCamCon::trackArea(int output) const {
    if (output < kFirstTrackArea || output > kLastTrackArea) {
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "output %1 does not exist in the table interface "
                                        "(outputs %2..%3)")
                .arg(output)
                .arg(kFirstTrackArea)
                .arg(kLastTrackArea));
    }
    return output;
}

Result<QString> TableCamCon::readOutputName(int) {
    return missing(CamConCapability::OutputNames);
}

// A device without names holds the empty name: writing it changes nothing
// and is no failure (a program is written with its name along).
Status TableCamCon::writeOutputName(int, const QString& name) {
    if (name.isEmpty()) return success();
    return missing(CamConCapability::OutputNames);
}

Result<QString> TableCamCon::readProgramName(int) {
    return missing(CamConCapability::OutputNames);
}

Status TableCamCon::writeProgramName(int, const QString& name) {
    if (name.isEmpty()) return success();
    return missing(CamConCapability::OutputNames);
}

Result<QList<User>> TableCamCon::readUsers() {
    return missing(CamConCapability::Users);
}

Status TableCamCon::writeUser(const QString&, const User&) {
    return missing(CamConCapability::Users);
}

Status TableCamCon::deleteUser(const QString&) {
    return missing(CamConCapability::Users);
}

Result<EepromImage> TableCamCon::backup(const ProgressFn&) {
    return missing(CamConCapability::EepromBackup);
}

Status TableCamCon::restore(const EepromImage&, const ProgressFn&) {
    return missing(CamConCapability::EepromBackup);
}

Result<QList<int>> TableCamCon::scanBus(int, int, const ProgressFn&) {
    return missing(CamConCapability::BusScan);
}

Result<QByteArray> TableCamCon::raw(const QByteArray&) {
    return missing(CamConCapability::Terminal);
}

}  // namespace cambench::comm::table
