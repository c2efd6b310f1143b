#include "machine_connection.h"

#include "comm/device/family_registry.h"
#include "comm/device/protocol_registry.h"

namespace cambench {

namespace {

Error refused(const MachineDevice& device, const QString& what) {
    return Error::invalidData(QStringLiteral("%1: %2").arg(device.name, what));
}

// The protocol the device's options ask for: the one named, else the
// family's bus protocol where an address is given, else its default.
Result<const comm::ProtocolInfo*> chosenProtocol(const MachineDevice& device,
                                                 const comm::FamilyInfo& family) {
    const comm::ProtocolRegistry& protocols = comm::ProtocolRegistry::instance();
    QString id = device.option(QStringLiteral("protocol"));
    if (id.isEmpty() && !device.option(QStringLiteral("address")).isEmpty()) {
        for (const comm::ProtocolInfo* info : protocols.all())
            if (info->familyId == family.id && info->isBus) return info;
    }
    if (id.isEmpty()) id = family.defaultProtocol;
    const comm::ProtocolInfo* info = protocols.find(id);
    if (!info)
        return refused(device, QStringLiteral("unknown protocol \"%1\"; the protocols are %2.")
                                   .arg(id, protocols.idList()));
    if (info->familyId != family.id)
        return refused(device, QStringLiteral("the protocol \"%1\" is one of the %2 family, not "
                                              "of %3.")
                                   .arg(id, info->familyId, family.id));
    return info;
}

// A whole number option within [min, max], `fallback` when not given.
Result<int> numberOption(const MachineDevice& device, const QString& key, int fallback, int min,
                         int max) {
    const QString text = device.option(key);
    if (text.isEmpty()) return fallback;
    bool ok = false;
    const int value = text.toInt(&ok);
    if (!ok || value < min || value > max)
        return refused(device, QStringLiteral("\"%1\" must be a whole number from %2 to %3, not "
                                              "\"%4\".")
                                   .arg(key)
                                   .arg(min)
                                   .arg(max)
                                   .arg(text));
    return value;
}

}  // namespace

Result<MachineConnection> machineConnection(const MachineDevice& device) {
    const Result<const comm::FamilyInfo*> family =
        comm::FamilyRegistry::instance().usable(device.family);
    if (!family) return refused(device, family.error().message);
    const Result<const comm::ProtocolInfo*> protocol = chosenProtocol(device, **family);
    if (!protocol) return protocol.error();
    const comm::ProtocolInfo& info = **protocol;

    const Result<int> baud =
        numberOption(device, QStringLiteral("baud"), info.defaultSerial.baud, 50, 4000000);
    const bool addressed = !device.option(QStringLiteral("address")).isEmpty();
    const Result<int> address =
        numberOption(device, addressed ? QStringLiteral("address") : QStringLiteral("device"), 0, 0,
                     info.isBus ? info.lastDevice : 63);
    const Result<int> pcNumber = numberOption(device, QStringLiteral("pc-number"), 63, 0, 63);
    for (const Result<int>* number : {&baud, &address, &pcNumber})
        if (!*number) return number->error();
    if (addressed && !info.isBus)
        return refused(device, QStringLiteral("\"address\" is for devices on a bus; the %1 "
                                              "protocol has none.")
                                   .arg(info.id));

    std::unique_ptr<comm::ProtocolSettings> settings = info.makeSettings();
    QVariantMap map{{QStringLiteral("device"), *address}, {QStringLiteral("pcNumber"), *pcNumber}};
    const QString variant = device.option(QStringLiteral("variant")).trimmed().toLower();
    if (!variant.isEmpty()) {
        if (!settings->variantKeys().contains(variant))
            return refused(device,
                           QStringLiteral("\"variant\" must be one of %1, not \"%2\".")
                               .arg(settings->variantKeys().join(QStringLiteral(", ")), variant));
        map.insert(QStringLiteral("variant"), variant);
    }
    settings->fromMap(map);

    MachineConnection result;
    result.connection.port = device.option(QStringLiteral("port"));
    result.connection.serial = info.defaultSerial;
    result.connection.serial.baud = *baud;
    result.connection.protocol = info.id;
    result.protocol = comm::ProtocolSettingsPtr(std::move(settings));
    return result;
}

MachineDevice machineDeviceFor(const QString& name, const comm::ConnectionSettings& connection,
                               const comm::ProtocolSettings& protocol) {
    MachineDevice device;
    device.name = name;
    const comm::ProtocolInfo* info = comm::ProtocolRegistry::instance().find(protocol.protocolId());
    device.family = info ? info->familyId : QString();
    device.options = {{QStringLiteral("port"), connection.port},
                      {QStringLiteral("protocol"), protocol.protocolId()}};
    if (info && connection.serial.baud != info->defaultSerial.baud)
        device.options.append({QStringLiteral("baud"), QString::number(connection.serial.baud)});
    if (info && info->isBus)
        device.options.append({QStringLiteral("device"), QString::number(protocol.device())});
    const QString variant = protocol.toMap().value(QStringLiteral("variant")).toString();
    if (!variant.isEmpty() && variant != QLatin1String("auto"))
        device.options.append({QStringLiteral("variant"), variant});
    return device;
}

}  // namespace cambench
