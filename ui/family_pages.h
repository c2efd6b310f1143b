#pragma once

#include <QList>
#include <QString>

#include <functional>

namespace cambench {

class DeviceSession;
class SectionPage;

// A section page of one device family, registered from app/gui (one line
// per page). The window adds it to its list and shows it while the chosen
// or connected protocol belongs to that family; other families' pages hide.
struct FamilyPage {
    QString familyId;
    std::function<SectionPage*(DeviceSession* session)> create;
};

class FamilyPageRegistry {
public:
    static FamilyPageRegistry& instance();

    void add(FamilyPage page);
    QList<FamilyPage> all() const { return m_pages; }

private:
    QList<FamilyPage> m_pages;
};

// The family of the protocol `session` connects (or last connected) with.
QString sessionFamily(const DeviceSession& session);

}  // namespace cambench
