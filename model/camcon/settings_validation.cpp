#include "system_settings.h"

#include <QCoreApplication>

#include <cmath>
#include <limits>
#include <optional>

namespace cambench {

namespace {

bool isIntegerType(const QVariant& value) {
    switch (value.typeId()) {
        case QMetaType::Int:
        case QMetaType::UInt:
        case QMetaType::LongLong:
        case QMetaType::ULongLong:
        case QMetaType::Long:
        case QMetaType::ULong:
        case QMetaType::Short:
        case QMetaType::UShort:
        case QMetaType::Char:
        case QMetaType::SChar:
        case QMetaType::UChar:
            return true;
        default:
            return false;
    }
}

// Integers, and doubles without a fraction (JSON numbers arrive as doubles).
std::optional<qint64> integerValue(const QVariant& value) {
    if (isIntegerType(value)) {
        if (value.typeId() == QMetaType::ULongLong &&
            value.toULongLong() > quint64(std::numeric_limits<qint64>::max()))
            return std::nullopt;
        return value.toLongLong();
    }
    if (value.typeId() == QMetaType::Double) {
        const double d = value.toDouble();
        if (std::isfinite(d) && d == std::trunc(d) && std::abs(d) < 9.0e15) return qint64(d);
    }
    return std::nullopt;
}

// "0..20, 255" for the values of an Enum.
QString choiceRanges(const SettingSpec& spec) {
    QStringList parts;
    const auto& choices = spec.choices;
    for (int i = 0; i < choices.size();) {
        int j = i;
        while (j + 1 < choices.size() && choices.at(j + 1).value == choices.at(j).value + 1) ++j;
        parts << (j == i
                      ? QString::number(choices.at(i).value)
                      : QStringLiteral("%1..%2").arg(choices.at(i).value).arg(choices.at(j).value));
        i = j + 1;
    }
    return parts.join(QStringLiteral(", "));
}

QString rangeText(const SettingSpec& spec) {
    return QStringLiteral("%1..%2").arg(formatSettingValue(spec, spec.min),
                                        formatSettingValue(spec, spec.max));
}

QString textProblem(const SettingSpec& spec, const QVariant& value) {
    if (value.typeId() != QMetaType::QString)
        return QCoreApplication::translate("cambench::model", "a text is expected");
    const QString text = value.toString();
    if (text.size() > spec.maxLength) {
        return QCoreApplication::translate("cambench::model",
                                           "\"%1\" has %2 characters; at most %3 are allowed")
            .arg(text)
            .arg(text.size())
            .arg(spec.maxLength);
    }
    for (const QChar c : text) {
        if (c.unicode() < 0x20 || c.unicode() > 0xFF ||
            (c.unicode() >= 0x7F && c.unicode() < 0xA0)) {
            return QCoreApplication::translate(
                       "cambench::model",
                       "\"%1\" contains a character the device cannot store (only "
                       "printable Latin-1 characters are allowed)")
                .arg(text);
        }
    }
    return {};
}

QString numberProblem(const SettingSpec& spec, qint64 v) {
    const QString shown = formatSettingValue(spec, v);
    if (spec.kind == SettingKind::Enum) {
        for (const SettingChoice& c : spec.choices) {
            if (c.value == v) return {};
        }
        return QCoreApplication::translate("cambench::model",
                                           "%1 is not one of the allowed values %2")
            .arg(shown, choiceRanges(spec));
    }
    if (spec.excludeZero && v == 0) {
        return QCoreApplication::translate("cambench::model",
                                           "0 is not allowed; allowed are %1..-%3 and %3..%2")
            .arg(formatSettingValue(spec, spec.min), formatSettingValue(spec, spec.max),
                 formatSettingValue(spec, 1));
    }
    const bool isRef = spec.kind == SettingKind::InputRef || spec.kind == SettingKind::OutputRef;
    if (v < spec.min || v > spec.max) {
        return QCoreApplication::translate("cambench::model",
                                           "%1 is outside the allowed range %2%3")
            .arg(shown, rangeText(spec),
                 isRef ? QCoreApplication::translate("cambench::model", " (0 = none)") : QString());
    }
    if (spec.step > 1 && v % spec.step != 0) {
        return QCoreApplication::translate(
                   "cambench::model", "%1 is not a multiple of %2 (allowed are %3 in steps of %2)")
            .arg(shown)
            .arg(spec.step)
            .arg(rangeText(spec));
    }
    return {};
}

}  // namespace

const SettingSpec* findSetting(const QString& key) {
    for (const SettingSpec& spec : settingSpecs()) {
        if (key == QLatin1String(spec.key)) return &spec;
    }
    return nullptr;
}

QString formatSettingValue(const SettingSpec& spec, qint64 value) {
    if (spec.kind != SettingKind::Fixed || spec.decimals <= 0) return QString::number(value);
    qint64 scale = 1;
    for (int i = 0; i < spec.decimals; ++i) scale *= 10;
    const quint64 magnitude = value < 0 ? 0 - quint64(value) : quint64(value);
    return QStringLiteral("%1%2.%3")
        .arg(value < 0 ? QStringLiteral("-") : QString())
        .arg(magnitude / quint64(scale))
        .arg(magnitude % quint64(scale), spec.decimals, 10, QLatin1Char('0'));
}

QString settingValueProblem(const SettingSpec& spec, const QVariant& value) {
    if (spec.kind == SettingKind::Text) return textProblem(spec, value);
    const std::optional<qint64> number = integerValue(value);
    if (!number)
        return QCoreApplication::translate("cambench::model", "\"%1\" is not a whole number")
            .arg(value.toString());
    return numberProblem(spec, *number);
}

QStringList validateSettings(const SystemSettings& settings) {
    QStringList problems;
    for (auto it = settings.cbegin(); it != settings.cend(); ++it) {
        const SettingSpec* spec = findSetting(it.key());
        if (!spec) {
            problems << QCoreApplication::translate("cambench::model",
                                                    "%1: there is no such setting.")
                            .arg(it.key());
            continue;
        }
        const QString problem = settingValueProblem(*spec, *it);
        if (!problem.isEmpty()) problems << QStringLiteral("%1: %2.").arg(it.key(), problem);
    }
    return problems;
}

bool isRotaryAxis(const SystemSettings& settings) {
    return settings.value(QStringLiteral("axisType"), 0).toLongLong() == 0;
}

}  // namespace cambench
