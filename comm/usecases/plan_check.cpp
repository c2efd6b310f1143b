#include "plan_check.h"

namespace cambench::usecases {

Error PlanCheck::refusal(const DeviceInfo&, int) const {
    return Error::invalidData(problems.join(QLatin1Char('\n')));
}

PlanCheck checkPlan(const WritePlan&, const DeviceInfo&, const CheckContext&) {
    return {};
}

QString numberRanges(const QSet<int>&) {
    return {};
}

}  // namespace cambench::usecases
