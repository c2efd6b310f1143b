#include "camcon_device.h"

#include <QCoreApplication>

namespace cambench::comm {

Result<BusUsers> CamConDevice::scanUsers(const ProgressFn& progress) {
    if (!has(CamConCapability::BusScan)) return missing(CamConCapability::BusScan);
    const Result<QList<int>> found = scanBus(0, 63, progress);
    if (!found) return found.error();
    BusUsers users;
    for (int number : *found) users.users << BusUser{number, BusUser::CamCon, false};
    return users;
}

QString CamConDevice::lacks(CamConCapability capability) const {
    const QString ascii = QCoreApplication::translate(
        "cambench::comm", "the CamCon ASCII protocol (Standard or Multiuser)");
    const QString table = QCoreApplication::translate(
        "cambench::comm", "the CamCon table interface (3964R n96 or e38)");
    switch (capability) {
        case CamConCapability::Users:
            return QCoreApplication::translate("cambench::comm",
                                               "Users and rights exist only in %1.")
                .arg(ascii);
        case CamConCapability::EepromBackup:
            return QCoreApplication::translate("cambench::comm",
                                               "EEPROM backup and restore exist only in %1.")
                .arg(ascii);
        case CamConCapability::BusScan:
            return QCoreApplication::translate("cambench::comm",
                                               "A bus scan needs the Multiuser or the Cam-BUS "
                                               "protocol.");
        case CamConCapability::Terminal:
            return QCoreApplication::translate("cambench::comm", "Typed requests exist only in %1.")
                .arg(ascii);
        case CamConCapability::OutputNames:
            return QCoreApplication::translate("cambench::comm",
                                               "Output and program names exist only in %1.")
                .arg(ascii);
        case CamConCapability::PlcNetworks:
            return QCoreApplication::translate(
                "cambench::comm", "This protocol does not reach the PLC logic module.");
        case CamConCapability::DeadTimeModes:
            return QCoreApplication::translate("cambench::comm",
                                               "Dead-time modes exist only in %1.")
                .arg(table);
        case CamConCapability::AnalogueCams:
            return QCoreApplication::translate("cambench::comm", "Analogue cams exist only in %1.")
                .arg(table);
        case CamConCapability::EepromLock:
            return QCoreApplication::translate("cambench::comm",
                                               "The EEPROM lock exists only in %1.")
                .arg(table);
        case CamConCapability::ShortCommands:
            return QCoreApplication::translate(
                       "cambench::comm",
                       "The short commands of the S7-CP340 coupling exist only in %1.")
                .arg(table);
        case CamConCapability::ProgrammingProgram:
            return QCoreApplication::translate(
                       "cambench::comm",
                       "Editing a program other than the active one exists only in %1.")
                .arg(table);
    }
    return {};
}

Error CamConDevice::missing(CamConCapability capability) const {
    return Error::unsupported(lacks(capability));
}

Result<DeadTimeModes> CamConDevice::readDeadTimeModes(int) {
    return missing(CamConCapability::DeadTimeModes);
}

Status CamConDevice::writeDeadTimeMode(int, const OutputDeadTime&) {
    return missing(CamConCapability::DeadTimeModes);
}

Result<int> CamConDevice::readAnalogueOutputCount() {
    return missing(CamConCapability::AnalogueCams);
}

Result<AnalogueCamTrack> CamConDevice::readAnalogueCams(int) {
    return missing(CamConCapability::AnalogueCams);
}

Status CamConDevice::writeAnalogueCams(const AnalogueCamTrack&) {
    return missing(CamConCapability::AnalogueCams);
}

Result<ProgrammingProgram> CamConDevice::readProgrammingProgram() {
    return missing(CamConCapability::ProgrammingProgram);
}

Status CamConDevice::writeProgrammingProgram(const ProgrammingProgram&) {
    return missing(CamConCapability::ProgrammingProgram);
}

Result<bool> CamConDevice::readEepromLock() {
    return missing(CamConCapability::EepromLock);
}

Status CamConDevice::writeEepromLock(bool) {
    return missing(CamConCapability::EepromLock);
}

Result<QString> CamConDevice::identify() {
    const Result<DeviceInfo> info = readInfo();
    if (!info) return info.error();
    return QCoreApplication::translate("cambench::comm",
                                       "CamCon, EPROM %1, device %2, %3 outputs, %4 programs")
        .arg(info->epromDate)
        .arg(info->deviceNumber)
        .arg(info->outputs)
        .arg(info->programs);
}

Result<DeviceIdentity> CamConDevice::readIdentity() {
    const Result<DeviceInfo> info = readInfo();
    if (!info) return info.error();
    return camConIdentity(*info);
}

}  // namespace cambench::comm
