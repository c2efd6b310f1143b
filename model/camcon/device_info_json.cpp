#include "device_info_json.h"

#include <QCoreApplication>

#include "model/json_reader.h"

namespace cambench {

namespace {

constexpr qint64 kInt32Max = std::numeric_limits<qint32>::max();
constexpr qint64 kInt32Min = std::numeric_limits<qint32>::min();

// One integer member: its key, the pointer to it, its range and whether it
// must be a multiple of 8 (manual 5.3.6).
struct IntField {
    const char* key;
    const char* what;
    qint64 min;
    qint64 max;
    bool multipleOf8;
};

template <class T>
struct Bound {
    IntField field;
    T DeviceInfo::*member;
};

const Bound<int> kIntFields[] = {
    {{"deviceNumber", "device number", 0, 63, false}, &DeviceInfo::deviceNumber},
    {{"protocol", "protocol", 0, 4, false}, &DeviceInfo::protocol},
    {{"outputs", "number of outputs", 8, 200, true}, &DeviceInfo::outputs},
    {{"inputs", "number of inputs", 0, 200, true}, &DeviceInfo::inputs},
    {{"deadTimeOutputs", "number of dead-time outputs", 0, 200, true},
     &DeviceInfo::deadTimeOutputs},
    {{"programs", "number of programs", 1, 32768, false}, &DeviceInfo::programs},
    {{"cpuClock", "CPU clock", 0, 1, false}, &DeviceInfo::cpuClock},
    {{"temperature", "temperature", 0, 255, false}, &DeviceInfo::temperature},
};

const Bound<qint32> kInt32Fields[] = {
    {{"minPosition", "minimum position", kInt32Min, kInt32Max, false}, &DeviceInfo::minPosition},
    {{"maxPosition", "maximum position", kInt32Min, kInt32Max, false}, &DeviceInfo::maxPosition},
    {{"maxDeadTime", "maximum dead time", 0, kInt32Max, false}, &DeviceInfo::maxDeadTime},
    {{"freeCams", "free cams", 0, kInt32Max, false}, &DeviceInfo::freeCams},
    {{"programmedCams", "programmed cams", 0, kInt32Max, false}, &DeviceInfo::programmedCams},
    {{"programmedDeadTimes", "programmed dead times", 0, kInt32Max, false},
     &DeviceInfo::programmedDeadTimes},
    {{"ramSize", "RAM size", 0, kInt32Max, false}, &DeviceInfo::ramSize},
    {{"ramFree", "free RAM", 0, kInt32Max, false}, &DeviceInfo::ramFree},
    {{"serialEepromSize", "serial EEPROM size", 0, kInt32Max, false},
     &DeviceInfo::serialEepromSize},
    {{"parallelEepromSize", "parallel EEPROM size", 0, kInt32Max, false},
     &DeviceInfo::parallelEepromSize},
};

template <class T>
void readField(JsonReader& reader, const QJsonObject& object, const QString& path,
               const Bound<T>& bound, DeviceInfo& info) {
    const IntField& f = bound.field;
    const QString key = QLatin1String(f.key);
    const qint64 value = reader.integer(object, path, key, QLatin1String(f.what), f.min, f.max);
    if (f.multipleOf8 && value % 8 != 0) {
        reader.fail(JsonReader::member(path, key),
                    QCoreApplication::translate("cambench::model", "%1 %2 is not a multiple of 8")
                        .arg(QLatin1String(f.what))
                        .arg(value));
    }
    info.*bound.member = T(value);
}

}  // namespace

QJsonObject deviceInfoToJson(const DeviceInfo& info) {
    QJsonObject object;
    object.insert(QStringLiteral("epromDate"), info.epromDate);
    for (const auto& bound : kIntFields)
        object.insert(QLatin1String(bound.field.key), info.*bound.member);
    for (const auto& bound : kInt32Fields)
        object.insert(QLatin1String(bound.field.key), info.*bound.member);
    return object;
}

DeviceInfo readDeviceInfo(JsonReader& reader, const QJsonObject& object, const QString& path) {
    DeviceInfo info;
    info.epromDate = reader.string(object, path, QStringLiteral("epromDate"),
                                   QCoreApplication::translate("cambench::model", "EPROM date"));
    for (const auto& bound : kIntFields) readField(reader, object, path, bound, info);
    for (const auto& bound : kInt32Fields) readField(reader, object, path, bound, info);
    if (!reader.failed() && info.minPosition >= info.maxPosition) {
        reader.fail(
            JsonReader::member(path, QStringLiteral("maxPosition")),
            QCoreApplication::translate("cambench::model",
                                        "maximum position %1 is not above the minimum position %2")
                .arg(info.maxPosition)
                .arg(info.minPosition));
    }
    return info;
}

}  // namespace cambench
