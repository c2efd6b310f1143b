#include "read_everything.h"

namespace cambench::usecases {

Result<ReadEverything> readEverything(comm::CamConDevice&, const DeviceInfo&,
                                      const UseCaseProgress&) {
    return Error::usage(QStringLiteral("readEverything: not implemented yet"));
}

QMap<int, int> plcNetworkCounts(const SystemSettings&) {
    return {};
}

}  // namespace cambench::usecases
