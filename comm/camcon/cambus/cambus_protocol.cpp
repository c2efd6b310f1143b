#include "cambus_protocol.h"

#include "cambus_camcon.h"

#include "comm/camcon/ascii/ascii_protocol.h"

#include <QCoreApplication>

namespace cambench::comm {

namespace {

QString camBusId() {
    return QStringLiteral("cambus");
}

}  // namespace

CamBusProtocolSettings::CamBusProtocolSettings() {
    ascii.pcNumber = kCamBusDefaultPcNumber;
}

QString CamBusProtocolSettings::protocolId() const {
    return camBusId();
}

std::unique_ptr<ProtocolSettings> CamBusProtocolSettings::clone() const {
    // The clone reports to the same bus view.
    return std::make_unique<CamBusProtocolSettings>(*this);
}

QVariantMap CamBusProtocolSettings::toMap() const {
    return {{QStringLiteral("device"), ascii.device},
            {QStringLiteral("pcNumber"), ascii.pcNumber},
            {QStringLiteral("timeoutMs"), ascii.timeoutMs},
            {QStringLiteral("retries"), ascii.retries}};
}

void CamBusProtocolSettings::fromMap(const QVariantMap& map) {
    ascii.device = qBound(0, map.value(QStringLiteral("device"), ascii.device).toInt(), 63);
    ascii.pcNumber = qBound(0, map.value(QStringLiteral("pcNumber"), ascii.pcNumber).toInt(), 63);
    ascii.timeoutMs = qMax(0, map.value(QStringLiteral("timeoutMs"), ascii.timeoutMs).toInt());
    ascii.retries = qBound(0, map.value(QStringLiteral("retries"), ascii.retries).toInt(), 10);
}

ProtocolInfo camconCamBusProtocol() {
    ProtocolInfo info;
    info.id = camBusId();
    info.title = QCoreApplication::translate("cambench::comm", "CamCon Cam-BUS (RS485 token bus)");
    info.defaultSerial.baud = 38400;  // docs/protocols/cambus.md: 38400 8N1
    info.defaultSerial.inBandBreaks = true;
    info.isBus = true;
    info.listeningProbe = true;
    info.lastDevice = kCamBusLastUser;
    info.choiceTitle = QT_TRANSLATE_NOOP("cambench::comm", "Cam-BUS (RS485 token bus)");
    info.options = camConBusOptions(info.lastDevice);
    info.options[1].help = QT_TRANSLATE_NOOP(
        "cambench::comm",
        "this PC's own number on the Cam-BUS, usually 63; no other user of the bus (CamCon, "
        "display, another PC) may have it");
    info.makeSettings = [] { return std::make_unique<CamBusProtocolSettings>(); };
    info.connect = [](Transport& transport, const ProtocolSettings& settings,
                      const LineTiming& line) -> Result<std::unique_ptr<DeviceConnection>> {
        const auto* bus = dynamic_cast<const CamBusProtocolSettings*>(&settings);
        if (!bus)
            return Error::usage(
                QCoreApplication::translate("cambench::comm", "the %1 protocol got settings of %2")
                    .arg(camBusId(),
                         QCoreApplication::translate("cambench::comm", "another protocol")));
        CamBusStationConfig station;
        station.number = bus->ascii.pcNumber;
        station.baud = line.baud;
        return std::unique_ptr<DeviceConnection>(
            std::make_unique<CamBusCamCon>(transport, bus->ascii, line, station, bus->monitor));
    };
    return info;
}

}  // namespace cambench::comm
