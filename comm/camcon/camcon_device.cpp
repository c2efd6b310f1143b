#include "camcon_device.h"

namespace cambench::comm {

QString CamConDevice::lacks(CamConCapability capability) const {
    const QString ascii = QStringLiteral("the CamCon ASCII protocol (--protocol standard or multiuser)");
    const QString table =
        QStringLiteral("the CamCon table interface (--protocol 3964r-n96 or 3964r-e38)");
    switch (capability) {
    case CamConCapability::Users:
        return QStringLiteral("Users and rights exist only in %1.").arg(ascii);
    case CamConCapability::EepromBackup:
        return QStringLiteral("EEPROM backup and restore exist only in %1.").arg(ascii);
    case CamConCapability::BusScan:
        return QStringLiteral("A bus scan needs the Multiuser protocol (--protocol multiuser).");
    case CamConCapability::Terminal:
        return QStringLiteral("Typed requests exist only in %1.").arg(ascii);
    case CamConCapability::OutputNames:
        return QStringLiteral("Output and program names exist only in %1.").arg(ascii);
    case CamConCapability::PlcNetworks:
        return QStringLiteral("This protocol does not reach the PLC logic module.");
    case CamConCapability::DeadTimeModes:
        return QStringLiteral("Dead-time modes exist only in %1.").arg(table);
    case CamConCapability::AnalogueCams:
        return QStringLiteral("Analogue cams exist only in %1.").arg(table);
    case CamConCapability::EepromLock:
        return QStringLiteral("The EEPROM lock exists only in %1.").arg(table);
    case CamConCapability::ProgrammingProgram:
        return QStringLiteral("Editing a program other than the active one exists only in %1.")
            .arg(table);
    }
    return {};
}

Error CamConDevice::missing(CamConCapability capability) const {
    return Error::usage(lacks(capability));
}

Result<DeadTimeModes> CamConDevice::readDeadTimeModes(int) {
    return missing(CamConCapability::DeadTimeModes);
}

Status CamConDevice::writeDeadTimeMode(int, const OutputDeadTime&) {
    return missing(CamConCapability::DeadTimeModes);
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

}  // namespace cambench::comm
