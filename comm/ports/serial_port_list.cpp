#include "serial_port_list.h"

#include <QSerialPortInfo>
#include <QStringList>

namespace cambench::comm {

QString SerialPortEntry::details() const {
    QStringList extra;
    if (!manufacturer.isEmpty()) extra << manufacturer;
    if (!serialNumber.isEmpty()) extra << QStringLiteral("S/N %1").arg(serialNumber);
    if (vendorId >= 0 && productId >= 0)
        extra << QStringLiteral("%1:%2")
                     .arg(vendorId, 4, 16, QLatin1Char('0'))
                     .arg(productId, 4, 16, QLatin1Char('0'));
    if (extra.isEmpty()) return description;
    const QString joined = extra.join(QLatin1String(", "));
    return description.isEmpty() ? joined : QStringLiteral("%1 (%2)").arg(description, joined);
}

QString SerialPortEntry::label() const {
    const QString text = details();
    return text.isEmpty() ? location : QStringLiteral("%1 — %2").arg(location, text);
}

QList<SerialPortEntry> availableSerialPorts() {
    QList<SerialPortEntry> ports;
    const QList<QSerialPortInfo> infos = QSerialPortInfo::availablePorts();
    for (const QSerialPortInfo& info : infos) {
        SerialPortEntry entry;
        entry.location = info.systemLocation();
        entry.description = info.description();
        entry.manufacturer = info.manufacturer();
        entry.serialNumber = info.serialNumber();
        if (info.hasVendorIdentifier()) entry.vendorId = info.vendorIdentifier();
        if (info.hasProductIdentifier()) entry.productId = info.productIdentifier();
        ports << entry;
    }
    return ports;
}

}  // namespace cambench::comm
