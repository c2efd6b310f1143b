#include "ascii_protocol.h"

#include <QCoreApplication>

#include "ascii_camcon.h"

namespace cambench::comm {

QList<ProtocolOption> camConBusOptions(int lastDevice) {
    ProtocolOption device = ProtocolOption::number(
        QStringLiteral("device"), QStringLiteral("device"), 0, lastDevice, 0,
        QT_TRANSLATE_NOOP("cambench::comm", "Device number:"),
        QT_TRANSLATE_NOOP("cambench::comm", "the number of the CamCon to talk to on the bus"));
    device.alwaysWritten = true;
    return {device, ProtocolOption::number(
                        QStringLiteral("pc-number"), QStringLiteral("pcNumber"), 0, 63, 63,
                        QT_TRANSLATE_NOOP("cambench::comm", "PC number:"),
                        QT_TRANSLATE_NOOP("cambench::comm", "this PC's own number on the bus"))};
}

namespace {

// Functions, not namespace-scope QStrings: registration may run during
// another file's static initialisation.
QString standardId() {
    return QStringLiteral("standard");
}
QString multiuserId() {
    return QStringLiteral("multiuser");
}

ProtocolInfo asciiProtocol(Framing framing) {
    const bool multi = framing == Framing::Multiuser;
    ProtocolInfo info;
    info.id = multi ? multiuserId() : standardId();
    info.title =
        multi ? QCoreApplication::translate("cambench::comm", "CamCon ASCII, Multiuser (RS485 bus)")
              : QCoreApplication::translate("cambench::comm", "CamCon ASCII, Standard (RS232)");
    info.defaultSerial.baud = multi ? 38400 : 9600;  // notes 1, both 8N1
    info.isBus = multi;
    info.lastDevice = multi ? 63 : 0;  // device numbers 0..63
    info.choiceTitle = multi ? QT_TRANSLATE_NOOP("cambench::comm", "Multiuser (RS485 bus)")
                             : QT_TRANSLATE_NOOP("cambench::comm", "Standard (point to point)");
    // A Standard line is point to point: no numbers to give.
    if (multi) info.options = camConBusOptions(info.lastDevice);
    info.makeSettings = [framing] { return std::make_unique<AsciiProtocolSettings>(framing); };
    info.connect = [](Transport& transport, const ProtocolSettings& settings,
                      const LineTiming& line) -> Result<std::unique_ptr<DeviceConnection>> {
        const auto* ascii = dynamic_cast<const AsciiProtocolSettings*>(&settings);
        if (!ascii)
            return Error::usage(
                QCoreApplication::translate("cambench::comm", "the %1 protocol got settings of %2")
                    .arg(settings.protocolId(),
                         QCoreApplication::translate("cambench::comm", "another protocol")));
        return std::unique_ptr<DeviceConnection>(
            std::make_unique<AsciiCamCon>(transport, ascii->ascii, line));
    };
    return info;
}

}  // namespace

QString AsciiProtocolSettings::protocolId() const {
    return ascii.framing == Framing::Multiuser ? multiuserId() : standardId();
}

std::unique_ptr<ProtocolSettings> AsciiProtocolSettings::clone() const {
    return std::make_unique<AsciiProtocolSettings>(*this);
}

int AsciiProtocolSettings::device() const {
    return ascii.framing == Framing::Multiuser ? ascii.device : -1;
}

QVariantMap AsciiProtocolSettings::toMap() const {
    return {{QStringLiteral("device"), ascii.device},
            {QStringLiteral("pcNumber"), ascii.pcNumber},
            {QStringLiteral("timeoutMs"), ascii.timeoutMs},
            {QStringLiteral("retries"), ascii.retries}};
}

void AsciiProtocolSettings::fromMap(const QVariantMap& map) {
    ascii.device = qBound(0, map.value(QStringLiteral("device"), ascii.device).toInt(), 63);
    ascii.pcNumber = qBound(0, map.value(QStringLiteral("pcNumber"), ascii.pcNumber).toInt(), 63);
    ascii.timeoutMs = qMax(0, map.value(QStringLiteral("timeoutMs"), ascii.timeoutMs).toInt());
    ascii.retries = qBound(0, map.value(QStringLiteral("retries"), ascii.retries).toInt(), 10);
}

QList<ProtocolInfo> camconAsciiProtocols() {
    return {asciiProtocol(Framing::Standard), asciiProtocol(Framing::Multiuser)};
}

}  // namespace cambench::comm
