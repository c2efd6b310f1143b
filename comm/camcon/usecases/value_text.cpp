#include "value_text.h"

#include "model/camcon/plc_file.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>

namespace cambench::usecases {

QString camsText(const Track& track) {
    if (track.cams.isEmpty()) return QCoreApplication::translate("cambench::usecases", "no cams");
    QStringList cams;
    for (const Cam& cam : track.cams) cams << QStringLiteral("%1..%2").arg(cam.on).arg(cam.off);
    return cams.join(QLatin1String(", "));
}

QString deadTimeText(qint32 tenthsMs) {
    return QStringLiteral("%1 ms").arg(QString::number(tenthsMs / 10.0, 'f', 1));
}

QString deadTimeModeText(const OutputDeadTime& deadTime) {
    switch (deadTime.mode) {
        case DeadTimeMode::Normal:
            return QCoreApplication::translate("cambench::usecases", "normal, %1")
                .arg(deadTimeText(deadTime.normal));
        case DeadTimeMode::SeparateOnOff:
            return QCoreApplication::translate("cambench::usecases",
                                               "on/off, switch-on %1, switch-off %2")
                .arg(deadTimeText(deadTime.on), deadTimeText(deadTime.off));
        case DeadTimeMode::PathTime:
            return QCoreApplication::translate("cambench::usecases",
                                               "path-time, switch-on %1, switching time %2")
                .arg(deadTimeText(deadTime.on), deadTimeText(deadTime.off));
    }
    return deadTimeModeKey(deadTime.mode);
}

QString nameText(const QString& name) {
    return name.isEmpty() ? QCoreApplication::translate("cambench::usecases", "no name")
                          : QLatin1Char('"') + name + QLatin1Char('"');
}

QString settingsText(const SystemSettings& values) {
    QStringList parts;
    for (auto it = values.cbegin(); it != values.cend(); ++it) {
        const SettingSpec* spec = findSetting(it.key());
        const QString value = spec && spec->kind != SettingKind::Text
                                  ? formatSettingValue(*spec, it->toLongLong())
                                  : QLatin1Char('"') + it->toString() + QLatin1Char('"');
        parts << QStringLiteral("%1=%2").arg(it.key(), value);
    }
    return parts.isEmpty() ? QCoreApplication::translate("cambench::usecases", "no values")
                           : parts.join(QLatin1String(", "));
}

QString userText(const std::optional<User>& user) {
    if (!user) return QCoreApplication::translate("cambench::usecases", "no such user");
    const int outputs =
        int(std::count(user->outputAccess.cbegin(), user->outputAccess.cend(), true));
    return QCoreApplication::translate("cambench::usecases", "user %1 with rights 0x%2 and %3")
        .arg(nameText(user->name))
        .arg(user->rights, 2, 16, QLatin1Char('0'))
        .arg(user->allOutputs
                 ? QCoreApplication::translate("cambench::usecases", "all outputs")
                 : QCoreApplication::translate("cambench::usecases", "%1 outputs").arg(outputs));
}

QString plcText(const PlcNetwork& network) {
    const int used = int(std::count_if(network.symbols.cbegin(), network.symbols.cend(),
                                       [](quint16 symbol) { return symbol != 0; }));
    return QCoreApplication::translate("cambench::usecases", "value %1, reset 0x%2, %3 symbols set")
        .arg(network.value)
        .arg(network.reset, 4, 16, QLatin1Char('0'))
        .arg(used);
}

QString analogueCamsText(const AnalogueCamTrack& track) {
    if (track.points.isEmpty())
        return QCoreApplication::translate("cambench::usecases", "no base points");
    // Every point: a changed one in the middle must be visible.
    QStringList points;
    for (const AnaloguePoint& point : track.points)
        points << QStringLiteral("%1 \u2192 %2").arg(point.position).arg(point.value);
    return QCoreApplication::translate("cambench::usecases", "%n base point(s): %1", "",
                                       int(track.points.size()))
        .arg(points.join(QStringLiteral(", ")));
}

QString programmingProgramText(const ProgrammingProgram& programming) {
    switch (programming.selectMode) {
        case 0:
            return QCoreApplication::translate("cambench::usecases", "program %1, changed slowly")
                .arg(programming.program);
        case 1:
            return QCoreApplication::translate("cambench::usecases",
                                               "program %1, changed directly (within one cycle)")
                .arg(programming.program);
        case 2:
            return QCoreApplication::translate("cambench::usecases",
                                               "program %1, changed at the actual value %2")
                .arg(programming.program)
                .arg(programming.switchValue);
    }
    return QCoreApplication::translate("cambench::usecases", "program %1, select mode %2")
        .arg(programming.program)
        .arg(programming.selectMode);
}

QString eepromLockText(bool locked) {
    return locked ? QCoreApplication::translate("cambench::usecases",
                                                "locked (changes stay in RAM only)")
                  : QCoreApplication::translate("cambench::usecases", "unlocked");
}

QString trackLabel(int program, int output) {
    return QCoreApplication::translate("cambench::usecases", "program %1, output %2")
        .arg(program)
        .arg(output);
}

QString deadTimeLabel(int output) {
    return QCoreApplication::translate("cambench::usecases", "dead time of output %1").arg(output);
}

QString deadTimeModeLabel(int output) {
    return QCoreApplication::translate("cambench::usecases", "dead-time mode of output %1")
        .arg(output);
}

QString outputNameLabel(int output) {
    return QCoreApplication::translate("cambench::usecases", "name of output %1").arg(output);
}

QString programNameLabel(int program) {
    return QCoreApplication::translate("cambench::usecases", "name of program %1").arg(program);
}

QString settingsLabel(const QString& group, const SystemSettings& keys) {
    return QCoreApplication::translate("cambench::usecases", "settings %1 (%2)")
        .arg(group, keys.keys().join(QLatin1String(", ")));
}

QString userLabel(const QString& name) {
    return QCoreApplication::translate("cambench::usecases", "user %1").arg(nameText(name));
}

QString plcLabel(const PlcNetwork& network) {
    return QCoreApplication::translate("cambench::usecases", "PLC network %1%2")
        .arg(plcAreaLetter(network.area))
        .arg(network.number);
}

QString analogueCamsLabel(int analogueOutput) {
    return QCoreApplication::translate("cambench::usecases", "analogue output %1")
        .arg(analogueOutput);
}

QString programmingProgramLabel() {
    return QCoreApplication::translate("cambench::usecases", "programming program");
}

QString eepromLockLabel() {
    return QCoreApplication::translate("cambench::usecases", "EEPROM lock");
}

}  // namespace cambench::usecases
