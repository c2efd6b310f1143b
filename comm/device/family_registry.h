#pragma once

#include "id_registry.h"

#include "model/result.h"

#include <QList>
#include <QString>

#include <memory>

namespace cambench::comm {

// A family of devices CamBench knows (the CamCon cam controllers, the MC-1
// motion controllers, the Compax3 drives): its id, its title and whether
// this build can talk to it. Families register from app/ (one line each),
// as protocols do; nothing else lists them. A family that is announced but
// not built yet is registered with `built` false and the reason, so that a
// technician asking for it is told so instead of being told it does not
// exist.
struct FamilyInfo {
    QString id;               // "camcon": the CLI's --family value, the files' "family"
    QString title;            // "Digitronic CamCon" (English; ui/ translates)
    QString defaultProtocol;  // a ProtocolInfo::id of this family
    bool built = false;
    QString notBuilt;  // why it cannot be used yet (when !built)

    // A family known by name whose protocol, simulator and pages are not
    // built yet.
    static FamilyInfo announced(const QString& id, const QString& title,
                                const QString& defaultProtocol);
};

class FamilyRegistry : public IdRegistry<FamilyInfo, &FamilyInfo::id> {
public:
    static FamilyRegistry& instance();

    // The family `id` names when this build can talk to it; otherwise a
    // usage error naming the families there are, or saying it is not built.
    Result<const FamilyInfo*> usable(const QString& id) const;
    // The family a command line without --family means: the first built
    // one registered (app/registry registers the CamCon first).
    QString defaultId() const;
};

}  // namespace cambench::comm
