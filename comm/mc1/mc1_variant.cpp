#include "mc1_variant.h"

namespace cambench::comm {

QList<Mc1Variant> allMc1Variants() {
    return {Mc1Variant::Mc100V1, Mc1Variant::Mc100V2, Mc1Variant::Mc200V1, Mc1Variant::Mc200V2};
}

QString mc1VariantKey(Mc1Variant variant) {
    switch (variant) {
        case Mc1Variant::Mc100V1:
            return QStringLiteral("mc100v1");
        case Mc1Variant::Mc100V2:
            return QStringLiteral("mc100v2");
        case Mc1Variant::Mc200V1:
            return QStringLiteral("mc200v1");
        case Mc1Variant::Mc200V2:
            return QStringLiteral("mc200v2");
    }
    return {};
}

std::optional<Mc1Variant> mc1VariantFromKey(const QString& key) {
    for (Mc1Variant variant : allMc1Variants())
        if (mc1VariantKey(variant) == key.trimmed().toLower()) return variant;
    return std::nullopt;
}

QString mc1VariantName(Mc1Variant variant) {
    switch (variant) {
        case Mc1Variant::Mc100V1:
            return QStringLiteral("MC100 V1");
        case Mc1Variant::Mc100V2:
            return QStringLiteral("MC100 V2");
        case Mc1Variant::Mc200V1:
            return QStringLiteral("MC200 V1");
        case Mc1Variant::Mc200V2:
            return QStringLiteral("MC200 V2");
    }
    return {};
}

bool isMc200(Mc1Variant variant) {
    return variant == Mc1Variant::Mc200V1 || variant == Mc1Variant::Mc200V2;
}

int mc1VariableBits(Mc1Variant variant) {
    return isMc200(variant) ? 32 : 24;
}

}  // namespace cambench::comm
