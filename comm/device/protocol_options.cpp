#include "protocol_options.h"

namespace cambench::comm {

namespace {

// The protocols of `familyId` that take `name`, by id.
QStringList protocolsTaking(const QString& familyId, const QString& name) {
    QStringList ids;
    for (const ProtocolInfo* protocol : ProtocolRegistry::instance().all())
        if (protocol->familyId == familyId && declaredOption(*protocol, name)) ids << protocol->id;
    return ids;
}

bool takesAll(const ProtocolInfo& protocol, const OptionValues& values) {
    for (const auto& [name, text] : values)
        if (!declaredOption(protocol, name)) return false;
    return true;
}

Status checkValue(const ProtocolOption& option, const QString& named, const QString& text) {
    if (option.isChoice()) {
        if (option.choices.contains(text.trimmed().toLower())) return success();
        return Error::usage(QStringLiteral("%1 must be one of %2, not \"%3\"")
                                .arg(named, option.choices.join(QStringLiteral(", ")), text));
    }
    bool ok = false;
    const int value = text.toInt(&ok, 10);
    if (ok && value >= option.min && value <= option.max) return success();
    return Error::usage(QStringLiteral("%1 must be a whole number from %2 to %3, not \"%4\"")
                            .arg(named)
                            .arg(option.min)
                            .arg(option.max)
                            .arg(text));
}

}  // namespace

QString commandLineOption(const QString& name) {
    return QStringLiteral("--") + name;
}

QString fileKey(const QString& name) {
    return QLatin1Char('"') + name + QLatin1Char('"');
}

QStringList protocolOptionNames() {
    QStringList names;
    for (const ProtocolInfo* protocol : ProtocolRegistry::instance().all())
        for (const ProtocolOption& option : protocol->options)
            for (const QString& name : QStringList{option.name} + option.aliases)
                if (!names.contains(name)) names << name;
    return names;
}

const ProtocolOption* declaredOption(const ProtocolInfo& protocol, const QString& name) {
    for (const ProtocolOption& option : protocol.options)
        if (option.isCalled(name)) return &option;
    return nullptr;
}

QStringList familiesTaking(const QString& name, const QString& value) {
    QStringList families;
    for (const ProtocolInfo* protocol : ProtocolRegistry::instance().all()) {
        const ProtocolOption* option = declaredOption(*protocol, name);
        if (!option || families.contains(protocol->familyId)) continue;
        if (option->isChoice() && !option->choices.contains(value.trimmed().toLower())) continue;
        families << protocol->familyId;
    }
    return families;
}

Result<const ProtocolInfo*> protocolTaking(const QString& familyId, const QString& preferred,
                                           const OptionValues& values, OptionNaming naming) {
    const ProtocolRegistry& registry = ProtocolRegistry::instance();
    if (const ProtocolInfo* first = registry.find(preferred); first && takesAll(*first, values))
        return first;
    for (const ProtocolInfo* protocol : registry.all())
        if (protocol->familyId == familyId && takesAll(*protocol, values)) return protocol;
    for (const auto& [name, text] : values)
        if (protocolsTaking(familyId, name).isEmpty())
            return Error::usage(QStringLiteral("%1 is not an option of the %2 family's protocols")
                                    .arg(naming(name), familyId));
    return Error::usage(
        QStringLiteral("no protocol of the %1 family takes all of %2 at once").arg(familyId, [&] {
            QStringList names;
            for (const auto& [name, text] : values) names << naming(name);
            return names.join(QStringLiteral(", "));
        }()));
}

Status checkOptionValues(const ProtocolInfo& protocol, const OptionValues& values,
                         OptionNaming naming) {
    for (const auto& [name, text] : values) {
        if (const ProtocolOption* option = declaredOption(protocol, name)) {
            if (const Status fits = checkValue(*option, naming(name), text); !fits) return fits;
            continue;
        }
        const QStringList takers = protocolsTaking(protocol.familyId, name);
        return Error::usage(
            takers.isEmpty()
                ? QStringLiteral("%1 is not an option of the %2 protocol")
                      .arg(naming(name), protocol.id)
                : QStringLiteral("%1 is not an option of the %2 protocol; %3 take%4 it")
                      .arg(naming(name), protocol.id, takers.join(QStringLiteral(", ")),
                           takers.size() == 1 ? QStringLiteral("s") : QString()));
    }
    return success();
}

std::unique_ptr<ProtocolSettings> settingsWith(const ProtocolInfo& protocol,
                                               const OptionValues& values, int timeoutMs) {
    std::unique_ptr<ProtocolSettings> settings = protocol.makeSettings();
    QVariantMap map = settings->toMap();
    if (timeoutMs > 0) map.insert(QStringLiteral("timeoutMs"), timeoutMs);
    for (const auto& [name, text] : values) {
        const ProtocolOption* option = declaredOption(protocol, name);
        if (!option) continue;
        map.insert(option->settingsKey, option->isChoice() ? QVariant(text.trimmed().toLower())
                                                           : QVariant(text.toInt()));
    }
    settings->fromMap(map);
    return settings;
}

OptionValues optionValuesOf(const ProtocolInfo& protocol, const ProtocolSettings& settings) {
    const QVariantMap map = settings.toMap();
    OptionValues values;
    for (const ProtocolOption& option : protocol.options) {
        const QString text = map.value(option.settingsKey).toString();
        const QString fallback =
            option.isChoice() ? option.choices.first() : QString::number(option.fallback);
        if (option.alwaysWritten || (!text.isEmpty() && text != fallback))
            values << qMakePair(option.name, text);
    }
    return values;
}

}  // namespace cambench::comm
