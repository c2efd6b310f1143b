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

void FamilyRegistry::add(FamilyInfo info) {
    for (auto& existing : m_families) {
        if (existing->id == info.id) {
            *existing = std::move(info);  // registering again replaces
            return;
        }
    }
    m_families.append(std::make_shared<FamilyInfo>(std::move(info)));
}

const FamilyInfo* FamilyRegistry::find(const QString& id) const {
    for (const auto& info : m_families)
        if (info->id.compare(id, Qt::CaseInsensitive) == 0) return info.get();
    return nullptr;
}

QList<const FamilyInfo*> FamilyRegistry::all() const {
    QList<const FamilyInfo*> list;
    for (const auto& info : m_families) list.append(info.get());
    return list;
}

QString FamilyRegistry::idList() const {
    QStringList ids;
    for (const auto& info : m_families) ids.append(info->id);
    return ids.join(QStringLiteral(", "));
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

}  // namespace cambench::comm
