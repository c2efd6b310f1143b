#include "family_backup.h"

namespace cambench::usecases {

BackupRegistry& BackupRegistry::instance() {
    static BackupRegistry registry;
    return registry;
}

void BackupRegistry::add(const QString& familyId, std::shared_ptr<const FamilyBackup> part) {
    m_parts.insert(familyId, std::move(part));
}

const FamilyBackup* BackupRegistry::find(const QString& familyId) const {
    const auto it = m_parts.constFind(familyId);
    return it == m_parts.cend() ? nullptr : it->get();
}

}  // namespace cambench::usecases
