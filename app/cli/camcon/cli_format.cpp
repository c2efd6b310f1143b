#include "cli_format.h"

namespace cambench::cli {

QList<QPair<QString, QVariant>> deviceInfoEntries(const DeviceInfo& info) {
    return {
        {QStringLiteral("eprom"), info.epromDate},
        {QStringLiteral("deviceNumber"), info.deviceNumber},
        {QStringLiteral("protocol"), info.protocol},
        {QStringLiteral("outputs"), info.outputs},
        {QStringLiteral("inputs"), info.inputs},
        {QStringLiteral("deadTimeOutputs"), info.deadTimeOutputs},
        {QStringLiteral("programs"), info.programs},
        {QStringLiteral("minPosition"), info.minPosition},
        {QStringLiteral("maxPosition"), info.maxPosition},
        {QStringLiteral("maxDeadTime"), info.maxDeadTime},
        {QStringLiteral("cpuClock"), info.cpuClock},
        {QStringLiteral("temperature"), info.temperature},
        {QStringLiteral("freeCams"), info.freeCams},
        {QStringLiteral("programmedCams"), info.programmedCams},
        {QStringLiteral("programmedDeadTimes"), info.programmedDeadTimes},
        {QStringLiteral("ramSize"), info.ramSize},
        {QStringLiteral("ramFree"), info.ramFree},
        {QStringLiteral("serialEepromSize"), info.serialEepromSize},
        {QStringLiteral("parallelEepromSize"), info.parallelEepromSize},
    };
}

QJsonObject deviceInfoJson(const DeviceInfo& info) {
    QJsonObject object;
    for (const auto& [key, value] : deviceInfoEntries(info)) {
        object.insert(key, QJsonValue::fromVariant(value));
    }
    return object;
}

QString rightsText(quint32 rights) {
    static const QPair<quint32, const char*> kRights[] = {
        {User::ProgramSelection, "program selection"},
        {User::Programming, "programming"},
        {User::SystemSettings, "system settings"},
        {User::DeviceConfiguration, "device configuration"},
        {User::PlcMenu, "PLC menu"},
        {User::AllOutputs, "all outputs"},
        {User::UserMenu, "user menu"},
    };
    QStringList names;
    for (const auto& [bit, name] : kRights) {
        if (rights & bit) names.append(QLatin1String(name));
    }
    return names.isEmpty() ? QStringLiteral("none") : names.join(QLatin1String(", "));
}

QString printableBytes(const QByteArray& bytes) {
    QString text;
    for (char c : bytes) {
        const auto byte = quint8(c);
        if (byte >= 0x20 && byte < 0x7F && c != '\\') {
            text.append(QLatin1Char(c));
        } else {
            text.append(QLatin1String("\\x") +
                        QString::number(byte, 16).rightJustified(2, u'0').toUpper());
        }
    }
    return text;
}

QString keyValueLines(const QList<QPair<QString, QVariant>>& entries) {
    QString text;
    for (const auto& [key, value] : entries) {
        text += QStringLiteral("%1: %2\n").arg(key, value.toString());
    }
    return text;
}

QList<int> onNumbers(const QList<bool>& bits) {
    QList<int> numbers;
    for (int i = 0; i < bits.size(); ++i) {
        if (bits.at(i)) numbers.append(i + 1);
    }
    return numbers;
}

QString numberList(const QList<int>& numbers) {
    QStringList texts;
    for (int n : numbers) texts.append(QString::number(n));
    return texts.isEmpty() ? QStringLiteral("none") : texts.join(u',');
}

QJsonArray jsonNumbers(const QList<int>& numbers) {
    QJsonArray array;
    for (int n : numbers) array.append(n);
    return array;
}

}  // namespace cambench::cli
