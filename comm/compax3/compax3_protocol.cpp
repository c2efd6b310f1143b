#include "compax3_protocol.h"

#include "compax3_drive.h"
#include "compax3_syntax.h"

#include <QCoreApplication>

namespace cambench::comm {

QString Compax3ProtocolSettings::protocolId() const {
    return m_rs485 ? QStringLiteral("compax3-rs485") : QStringLiteral("compax3");
}

std::unique_ptr<ProtocolSettings> Compax3ProtocolSettings::clone() const {
    return std::make_unique<Compax3ProtocolSettings>(*this);
}

QVariantMap Compax3ProtocolSettings::toMap() const {
    return {{QStringLiteral("device"), address}, {QStringLiteral("timeoutMs"), timeout}};
}

void Compax3ProtocolSettings::fromMap(const QVariantMap& map) {
    address = qBound(0, map.value(QStringLiteral("device"), address).toInt(), kCompax3LastAddress);
    timeout = qMax(0, map.value(QStringLiteral("timeoutMs"), timeout).toInt());
}

namespace {

ProtocolInfo compax3Protocol(bool rs485) {
    ProtocolInfo info;
    info.id = rs485 ? QStringLiteral("compax3-rs485") : QStringLiteral("compax3");
    info.title = rs485 ? QCoreApplication::translate("cambench::comm", "Compax3 ASCII (RS485)")
                       : QCoreApplication::translate("cambench::comm", "Compax3 ASCII (RS232)");
    info.defaultSerial.baud = 115200;
    info.defaultSerial.flowControl = 'H';  // RTS/CTS, as Parker's tools connect
    info.isBus = rs485;
    info.lastDevice = rs485 ? kCompax3LastAddress : 0;
    info.numbersAreAddresses = rs485;
    info.note = rs485 ? QT_TRANSLATE_NOOP("cambench::comm",
                                          "RS485, 115200 8N1 unless set otherwise in the drive.")
                      : QT_TRANSLATE_NOOP("cambench::comm",
                                          "RS232, 115200 8N1 with RTS/CTS unless set otherwise in "
                                          "the drive; a null-modem cable with RTS/CTS.");
    if (rs485) {
        ProtocolOption address = ProtocolOption::number(
            QStringLiteral("address"), QStringLiteral("device"), 0, kCompax3LastAddress, 0,
            QT_TRANSLATE_NOOP("cambench::comm", "Drive address:"),
            QT_TRANSLATE_NOOP("cambench::comm",
                              "the drive's RS485 address (C3 ServoManager, \"RS485 settings\"); "
                              "Scan bus lists the addresses that answer"));
        // Machine files written before the option had its name say "device".
        address.aliases = {QStringLiteral("device")};
        address.alwaysWritten = true;
        info.options = {address};
    }
    info.makeSettings = [rs485] { return std::make_unique<Compax3ProtocolSettings>(rs485); };
    info.connect = [rs485, id = info.id](
                       Transport& transport, const ProtocolSettings& settings,
                       const LineTiming& line) -> Result<std::unique_ptr<DeviceConnection>> {
        const auto* compax3 = dynamic_cast<const Compax3ProtocolSettings*>(&settings);
        if (!compax3)
            return Error::usage(
                QCoreApplication::translate("cambench::comm", "the %1 protocol got settings of %2")
                    .arg(id, settings.protocolId()));
        return std::unique_ptr<DeviceConnection>(std::make_unique<Compax3Drive>(
            transport, id, rs485 ? compax3->address : -1, compax3->timeout, line));
    };
    return info;
}

}  // namespace

QList<ProtocolInfo> compax3Protocols() {
    return {compax3Protocol(false), compax3Protocol(true)};
}

}  // namespace cambench::comm
