#include "mc1_protocol.h"

#include <QCoreApplication>

namespace cambench::comm {

std::unique_ptr<ProtocolSettings> Mc1ProtocolSettings::clone() const {
    return std::make_unique<Mc1ProtocolSettings>(*this);
}

QStringList Mc1ProtocolSettings::variantKeys() {
    QStringList keys{QStringLiteral("auto")};
    for (Mc1Variant variant : allMc1Variants()) keys << mc1VariantKey(variant);
    return keys;
}

QVariantMap Mc1ProtocolSettings::toMap() const {
    QStringList axes;
    for (int axis : mc1.axes.value_or(QList<int>())) axes << QString::number(axis);
    return {{QStringLiteral("variant"),
             mc1.variant ? mc1VariantKey(*mc1.variant) : QStringLiteral("auto")},
            {QStringLiteral("timeoutMs"), mc1.timeoutMs},
            {QStringLiteral("retries"), mc1.retries},
            // "" finds them (RDTABLE); "1,2" uses those.
            {QStringLiteral("axes"), axes.join(QLatin1Char(','))}};
}

void Mc1ProtocolSettings::fromMap(const QVariantMap& map) {
    if (map.contains(QStringLiteral("variant")))
        mc1.variant = mc1VariantFromKey(map.value(QStringLiteral("variant")).toString());
    mc1.timeoutMs = qMax(0, map.value(QStringLiteral("timeoutMs"), mc1.timeoutMs).toInt());
    mc1.retries = qBound(0, map.value(QStringLiteral("retries"), mc1.retries).toInt(), 10);
    if (map.contains(QStringLiteral("axes"))) {
        // A list that does not parse finds the axes rather than guessing.
        const Result<QList<int>> axes =
            parseMc1AxisList(map.value(QStringLiteral("axes")).toString());
        mc1.axes = axes ? std::optional<QList<int>>(*axes) : std::nullopt;
    }
}

std::unique_ptr<ProtocolSettings> Mc1AsciiProtocolSettings::clone() const {
    return std::make_unique<Mc1AsciiProtocolSettings>(*this);
}

QVariantMap Mc1AsciiProtocolSettings::toMap() const {
    return {{QStringLiteral("timeoutMs"), timeout}};
}

void Mc1AsciiProtocolSettings::fromMap(const QVariantMap& map) {
    timeout = qMax(0, map.value(QStringLiteral("timeoutMs"), timeout).toInt());
}

namespace {

Error otherSettings(const QString& protocol) {
    return Error::usage(
        QCoreApplication::translate("cambench::comm", "the %1 protocol got settings of %2")
            .arg(protocol, QCoreApplication::translate("cambench::comm", "another protocol")));
}

ProtocolInfo asciiProtocol() {
    ProtocolInfo info;
    info.id = QStringLiteral("mc1-ascii");
    info.title = QCoreApplication::translate("cambench::comm", "MC100 ASCII (RS232)");
    info.defaultSerial.baud = 9600;
    info.makeSettings = [] { return std::make_unique<Mc1AsciiProtocolSettings>(); };
    info.connect = [](Transport& transport, const ProtocolSettings& settings,
                      const LineTiming& line) -> Result<std::unique_ptr<DeviceConnection>> {
        const auto* ascii = dynamic_cast<const Mc1AsciiProtocolSettings*>(&settings);
        if (!ascii) return otherSettings(QStringLiteral("mc1-ascii"));
        return std::unique_ptr<DeviceConnection>(
            std::make_unique<Mc1AsciiController>(transport, ascii->timeout, line));
    };
    return info;
}

}  // namespace

QList<ProtocolInfo> mc1Protocols() {
    ProtocolInfo info;
    info.id = QStringLiteral("mc1");
    info.title = QCoreApplication::translate("cambench::comm", "MC-1 (RS232)");
    info.defaultSerial.baud = 9600;  // MC100: 9600 only; MC200: as set in the device
    info.defaultSerial.dtr = true;   // DTR high and RTS low power the MC200's driver
    info.defaultSerial.rts = false;
    info.options = {ProtocolOption::choice(
        QStringLiteral("variant"), QStringLiteral("variant"), Mc1ProtocolSettings::variantKeys(),
        QT_TRANSLATE_NOOP("cambench::comm", "Controller:"),
        QT_TRANSLATE_NOOP("cambench::comm",
                          "the controller variant to expect; auto (the default) probes and names "
                          "what it found"))};
    info.makeSettings = [] { return std::make_unique<Mc1ProtocolSettings>(); };
    info.connect = [](Transport& transport, const ProtocolSettings& settings,
                      const LineTiming& line) -> Result<std::unique_ptr<DeviceConnection>> {
        const auto* mc1 = dynamic_cast<const Mc1ProtocolSettings*>(&settings);
        if (!mc1) return otherSettings(QStringLiteral("mc1"));
        return std::unique_ptr<DeviceConnection>(
            std::make_unique<Mc1Controller>(transport, mc1->mc1, line));
    };
    return {info, asciiProtocol()};
}

}  // namespace cambench::comm
