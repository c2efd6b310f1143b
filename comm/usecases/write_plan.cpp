#include "write_plan.h"

namespace cambench::usecases {

int WritePlan::itemCount() const {
    return int(settings.size() + programNames.size() + tracks.size() + deadTimes.size() +
               outputNames.size() + users.size() + plcNetworks.size());
}

QList<SettingsWrite> settingsGroups(const SystemSettings&) {
    return {};
}

WritePlan planFromProject(const Project&, const Project&) {
    return {};
}

}  // namespace cambench::usecases
