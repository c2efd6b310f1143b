#include "family_registry.h"

#include <QStringList>

namespace cambench::comm {

FamilyInfo FamilyInfo::announced(const QString& id, const QString& title,
                                 const QString& defaultProtocol) {
    FamilyInfo info;
    info.id = id;
    info.title = title;
    info.defaultProtocol = defaultProtocol;
    info.notBuilt = QStringLiteral(
                        "The %1 family is not built into this CamBench yet: no protocol, "
                        "simulator or page of it exists here")
                        .arg(title);
    return info;
}

FamilyRegistry& FamilyRegistry::instance() {
    static FamilyRegistry registry;
    return registry;
}

Result<const FamilyInfo*> FamilyRegistry::usable(const QString& id) const {
    const FamilyInfo* family = find(id);
    if (!family) {
        return Error::usage(
            QStringLiteral("--family must be one of %1, not \"%2\"").arg(idList(), id));
    }
    if (!family->built) return Error::usage(family->notBuilt);
    return family;
}

QString FamilyRegistry::defaultId() const {
    for (const FamilyInfo* family : all())
        if (family->built) return family->id;
    return {};
}

}  // namespace cambench::comm
