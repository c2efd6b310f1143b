#include "machine_file.h"

#include "volatile_items.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QSet>

#include <cmath>

namespace cambench {

namespace {

Error refused(const QString& where, const QString& what) {
    return Error::invalidData(QStringLiteral("Machine file %1: %2").arg(where, what));
}

QString deviceLabel(int index, const QString& name) {
    return machineDeviceLabel(index, name);
}

// Text, or a whole number written as text; empty with `ok` false otherwise.
QString optionText(const QJsonValue& value, bool* ok) {
    *ok = true;
    if (value.isString()) return value.toString();
    if (value.isDouble()) {
        const double number = value.toDouble();
        if (std::floor(number) == number && std::abs(number) < 1e9)
            return QString::number(qint64(number));
    }
    *ok = false;
    return {};
}

// "volatile": ["V100-V199", "V12"]: a list of texts, each an item or a range.
Result<QStringList> volatileItemsOf(const QJsonValue& value, const QString& label) {
    const QString shape =
        QStringLiteral(
            "%1: \"volatile\" is a list of the items that change by themselves, as a comparison "
            "names them: [\"V100-V199\", \"V12\"].")
            .arg(label);
    if (!value.isArray()) return Error::invalidData(shape);
    QStringList items;
    for (const QJsonValue& item : value.toArray()) {
        if (!item.isString()) return Error::invalidData(shape);
        items << item.toString().trimmed();
    }
    if (const Status checked = checkVolatileItems(items, label); !checked) return checked.error();
    return items;
}

Result<MachineDevice> parseDevice(const QJsonValue& value, int index, const QString& where) {
    if (!value.isObject())
        return refused(where, QStringLiteral("%1 is not an object {\"name\": ..., \"family\": "
                                             "...}.")
                                  .arg(deviceLabel(index, {})));
    const QJsonObject object = value.toObject();
    MachineDevice device;
    device.name = object.value(QStringLiteral("name")).toString().trimmed();
    if (device.name.isEmpty())
        return refused(where, QStringLiteral("%1 has no \"name\"; give every device a name.")
                                  .arg(deviceLabel(index, {})));
    const QString label = deviceLabel(index, device.name);
    device.family = object.value(QStringLiteral("family")).toString();
    if (device.family.isEmpty())
        return refused(
            where,
            QStringLiteral("%1 has no \"family\" (`cambench-cli --help` lists them).").arg(label));
    const QStringList keys = machineDeviceKeys();
    // The file's order is lost in QJsonObject (sorted keys); the command
    // line does not depend on the order, and sorted is stable.
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (it.key() == QLatin1String("name") || it.key() == QLatin1String("family")) continue;
        if (it.key() == QLatin1String("identity")) {
            const Result<DeviceIdentity> identity =
                DeviceIdentity::fromJson(it.value(), QStringLiteral("%1: identity").arg(label));
            if (!identity) return refused(where, identity.error().message);
            device.identity = *identity;
            continue;
        }
        if (it.key() == QLatin1String("volatile")) {
            const Result<QStringList> items = volatileItemsOf(it.value(), label);
            if (!items) return refused(where, items.error().message);
            device.volatileItems = *items;
            continue;
        }
        if (!keys.contains(it.key()))
            return refused(where, QStringLiteral("%1: unknown key \"%2\"; a device's keys are "
                                                 "name, family, %3.")
                                      .arg(label, it.key(),
                                           (keys + QStringList{QStringLiteral("volatile"),
                                                               QStringLiteral("identity")})
                                               .join(QLatin1String(", "))));
        bool ok = false;
        const QString text = optionText(it.value(), &ok);
        if (!ok || text.isEmpty())
            return refused(
                where,
                QStringLiteral("%1: \"%2\" must be text or a whole number.").arg(label, it.key()));
        device.options.append({it.key(), text});
    }
    if (device.option(QStringLiteral("port")).isEmpty())
        return refused(where, QStringLiteral("%1 has no \"port\" (e.g. /dev/ttyUSB0, "
                                             "tcp://host:4001, sim).")
                                  .arg(label));
    return device;
}

// "shaft": {"from", "to", "axis", "per-turn"} into `machine`.
Status parseShaft(const QJsonValue& value, MachineFile& machine, const QString& where) {
    const QJsonObject shaft = value.toObject();
    if (!shaft.contains(QStringLiteral("from")) || !shaft.contains(QStringLiteral("to")))
        return refused(where, QStringLiteral("the shaft is {\"from\": DEVICE, \"to\": DEVICE}: "
                                             "the device whose axis drives it and the one that "
                                             "follows."));
    for (auto it = shaft.begin(); it != shaft.end(); ++it) {
        static const QStringList keys{QStringLiteral("from"), QStringLiteral("to"),
                                      QStringLiteral("axis"), QStringLiteral("per-turn")};
        if (!keys.contains(it.key()))
            return refused(where, QStringLiteral("the shaft has an unknown key \"%1\"; its keys "
                                                 "are from, to, axis and per-turn.")
                                      .arg(it.key()));
    }
    machine.shaftFrom = shaft.value(QStringLiteral("from")).toString();
    machine.shaftTo = shaft.value(QStringLiteral("to")).toString();
    for (const QString& end : {machine.shaftFrom, machine.shaftTo})
        if (!machine.device(end))
            return refused(where, QStringLiteral("the shaft's \"from\" and \"to\" must name "
                                                 "devices of the file (not \"%1\").")
                                      .arg(end));
    if (machine.shaftFrom == machine.shaftTo)
        return refused(where, QStringLiteral("the shaft runs from \"%1\" to itself; \"to\" "
                                             "names the device that follows.")
                                  .arg(machine.shaftFrom));
    if (shaft.contains(QStringLiteral("axis"))) {
        const double axis = shaft.value(QStringLiteral("axis")).toDouble(-1);
        if (axis < 1 || axis > 64 || std::floor(axis) != axis)
            return refused(where, QStringLiteral("the shaft's \"axis\" is the driving axis of "
                                                 "\"%1\": a whole number 1, 2, ...")
                                      .arg(machine.shaftFrom));
        machine.shaftAxis = int(axis);
    }
    if (shaft.contains(QStringLiteral("per-turn"))) {
        const double perTurn = shaft.value(QStringLiteral("per-turn")).toDouble(-1);
        if (!(perTurn > 0) || !std::isfinite(perTurn))
            return refused(where, QStringLiteral("the shaft's \"per-turn\" is how many units of "
                                                 "\"%1\" turn \"%2\" once: a number above 0.")
                                      .arg(machine.shaftFrom, machine.shaftTo));
        machine.shaftPerTurn = perTurn;
    }
    return success();
}

}  // namespace

QString machineDeviceLabel(int index, const QString& name) {
    return name.isEmpty() ? QStringLiteral("device %1").arg(index + 1)
                          : QStringLiteral("device %1 (%2)").arg(index + 1).arg(name);
}

QString MachineDevice::option(const QString& key) const {
    for (const auto& [name, value] : options)
        if (name == key) return value;
    return {};
}

QStringList MachineDevice::arguments() const {
    QStringList args{QStringLiteral("--family"), family};
    for (const auto& [name, value] : options) args << QStringLiteral("--") + name << value;
    return args;
}

const MachineDevice* MachineFile::device(const QString& name) const {
    for (const MachineDevice& device : devices)
        if (device.name == name) return &device;
    return nullptr;
}

namespace {

QStringList& protocolKeys() {
    static QStringList keys;
    return keys;
}

}  // namespace

QStringList machineDeviceKeys() {
    return QStringList{QStringLiteral("port"), QStringLiteral("protocol"), QStringLiteral("baud")} +
           protocolKeys();
}

void addMachineDeviceKeys(const QStringList& keys) {
    for (const QString& key : keys)
        if (!protocolKeys().contains(key)) protocolKeys() << key;
}

namespace {

// A JSON string or, for a whole number, the number.
QByteArray jsonValue(const QString& text, bool numberAllowed) {
    bool number = false;
    const qint64 value = text.toLongLong(&number);
    if (numberAllowed && number && QString::number(value) == text) return text.toUtf8();
    // QJsonDocument writes the escapes; the array's brackets are dropped.
    const QByteArray array = QJsonDocument(QJsonArray{text}).toJson(QJsonDocument::Compact);
    return array.mid(1, array.size() - 2);
}

QByteArray deviceJson(const MachineDevice& device) {
    // A whole number is written as one (a device number, a baud rate),
    // but a port and a protocol stay text whatever they look like.
    const auto numberAllowed = [](const QString& key) {
        return key != QLatin1String("port") && key != QLatin1String("protocol");
    };
    QByteArrayList members{"\"name\": " + jsonValue(device.name, false),
                           "\"family\": " + jsonValue(device.family, false)};
    for (const auto& [key, value] : device.options)
        members << jsonValue(key, false) + ": " + jsonValue(value, numberAllowed(key));
    if (!device.volatileItems.isEmpty()) {
        QByteArrayList items;
        for (const QString& item : device.volatileItems) items << jsonValue(item, false);
        members << "\"volatile\": [" + items.join(", ") + "]";
    }
    if (device.identity.known()) {
        QByteArrayList parts;
        for (auto it = device.identity.values().begin(); it != device.identity.values().end(); ++it)
            parts << jsonValue(it.key(), false) + ": " + jsonValue(it.value(), false);
        members << "\"identity\": {" + parts.join(", ") + "}";
    }
    return "{" + members.join(", ") + "}";
}

}  // namespace

QByteArray machineFileJson(const MachineFile& machine) {
    QByteArrayList devices;
    for (const MachineDevice& device : machine.devices) devices << "    " + deviceJson(device);
    QByteArray text = "{\n  \"machine\": " + jsonValue(machine.machine, false) +
                      ",\n  \"devices\": [\n" + devices.join(",\n") + "\n  ]";
    if (!machine.shaftFrom.isEmpty() || !machine.shaftTo.isEmpty()) {
        text += ",\n  \"shaft\": {\"from\": " + jsonValue(machine.shaftFrom, false) +
                ", \"to\": " + jsonValue(machine.shaftTo, false);
        // Written only when given, so that a file read and saved again
        // keeps the defaults it had (axis 1, 360 units a turn).
        if (machine.shaftAxis) text += ", \"axis\": " + QByteArray::number(*machine.shaftAxis);
        if (machine.shaftPerTurn)
            text += ", \"per-turn\": " + QByteArray::number(*machine.shaftPerTurn, 'g', 15);
        text += "}";
    }
    return text + "\n}\n";
}

Result<MachineFile> parseMachineFile(const QByteArray& bytes, const QString& where) {
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError)
        return refused(
            where,
            QStringLiteral("not JSON at byte %1 (%2).").arg(error.offset).arg(error.errorString()));
    if (!document.isObject())
        return refused(where, QStringLiteral("not a machine file: expected {\"machine\": ..., "
                                             "\"devices\": [...]}."));
    const QJsonObject root = document.object();
    for (auto it = root.begin(); it != root.end(); ++it) {
        if (it.key() != QLatin1String("machine") && it.key() != QLatin1String("devices") &&
            it.key() != QLatin1String("shaft"))
            return refused(where, QStringLiteral("unknown key \"%1\"; a machine file has machine, "
                                                 "devices and shaft.")
                                      .arg(it.key()));
    }
    MachineFile machine;
    machine.machine = root.value(QStringLiteral("machine")).toString().trimmed();
    if (machine.machine.isEmpty()) return refused(where, QStringLiteral("no \"machine\" name."));
    const QJsonArray devices = root.value(QStringLiteral("devices")).toArray();
    if (devices.isEmpty())
        return refused(where, QStringLiteral("no \"devices\": list the machine's devices."));
    QSet<QString> names;
    for (int i = 0; i < devices.size(); ++i) {
        Result<MachineDevice> device = parseDevice(devices.at(i), i, where);
        if (!device) return device.error();
        if (names.contains(device->name))
            return refused(where, QStringLiteral("%1: the name is given twice; each device needs "
                                                 "its own.")
                                      .arg(deviceLabel(i, device->name)));
        names.insert(device->name);
        machine.devices << *device;
    }
    if (root.contains(QStringLiteral("shaft")))
        if (const Status shaft = parseShaft(root.value(QStringLiteral("shaft")), machine, where);
            !shaft)
            return shaft.error();
    return machine;
}

}  // namespace cambench
