#include "machine_connection.h"

#include "comm/device/family_registry.h"
#include "comm/device/protocol_options.h"
#include "comm/device/protocol_registry.h"

namespace cambench {

namespace {

// The keys of a machine file's device that are the line's, not its
// protocol's (the command line's --port, --protocol, --baud).
const QString kPort = QStringLiteral("port");
const QString kProtocol = QStringLiteral("protocol");
const QString kBaud = QStringLiteral("baud");

Error refused(const MachineDevice& device, const QString& what) {
    return Error::invalidData(QStringLiteral("%1: %2").arg(device.name, what));
}

// The device's options its protocol declares (all but the line's).
comm::OptionValues protocolValuesOf(const MachineDevice& device) {
    comm::OptionValues values;
    for (const auto& [key, text] : device.options)
        if (key != kPort && key != kProtocol && key != kBaud) values << qMakePair(key, text);
    return values;
}

// The protocol the device's options ask for: the one named, else the
// family's default when it takes the options given, else the family's
// first that does (an "address": the family's bus of addressed devices).
Result<const comm::ProtocolInfo*> chosenProtocol(const MachineDevice& device,
                                                 const comm::FamilyInfo& family,
                                                 const comm::OptionValues& values) {
    const comm::ProtocolRegistry& protocols = comm::ProtocolRegistry::instance();
    const QString id = device.option(kProtocol);
    if (id.isEmpty()) {
        const Result<const comm::ProtocolInfo*> taking =
            comm::protocolTaking(family.id, family.defaultProtocol, values, comm::fileKey);
        if (!taking) return refused(device, taking.error().message + u'.');
        return taking;
    }
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

}  // namespace

Result<MachineConnection> machineConnection(const MachineDevice& device) {
    const Result<const comm::FamilyInfo*> family =
        comm::FamilyRegistry::instance().usable(device.family);
    if (!family) return refused(device, family.error().message);
    const comm::OptionValues values = protocolValuesOf(device);
    const Result<const comm::ProtocolInfo*> protocol = chosenProtocol(device, **family, values);
    if (!protocol) return protocol.error();
    const comm::ProtocolInfo& info = **protocol;

    int baud = info.defaultSerial.baud;
    if (const QString text = device.option(kBaud); !text.isEmpty()) {
        bool ok = false;
        baud = text.toInt(&ok);
        if (!ok || baud < 50 || baud > 4000000)
            return refused(device, QStringLiteral("\"baud\" must be a whole number from 50 to "
                                                  "4000000, not \"%1\".")
                                       .arg(text));
    }
    if (const Status fits = comm::checkOptionValues(info, values, comm::fileKey); !fits)
        return refused(device, fits.error().message + u'.');

    MachineConnection result;
    result.connection.port = device.option(kPort);
    result.connection.serial = info.defaultSerial;
    result.connection.serial.baud = baud;
    result.connection.protocol = info.id;
    result.protocol = comm::ProtocolSettingsPtr(comm::settingsWith(info, values));
    return result;
}

MachineDevice machineDeviceFor(const QString& name, const comm::ConnectionSettings& connection,
                               const comm::ProtocolSettings& protocol) {
    MachineDevice device;
    device.name = name;
    const comm::ProtocolInfo* info = comm::ProtocolRegistry::instance().find(protocol.protocolId());
    device.family = info ? info->familyId : QString();
    device.options = {{kPort, connection.port}, {kProtocol, protocol.protocolId()}};
    if (!info) return device;
    if (connection.serial.baud != info->defaultSerial.baud)
        device.options.append({kBaud, QString::number(connection.serial.baud)});
    device.options += comm::optionValuesOf(*info, protocol);
    return device;
}

}  // namespace cambench
