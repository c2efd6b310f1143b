#include "write_items.h"

namespace cambench::usecases {

Result<WriteReport> writeItems(comm::CamConDevice&, const DeviceInfo&, const WritePlan&,
                               const UseCaseProgress&) {
    return Error::usage(QStringLiteral("writeItems: not implemented yet"));
}

}  // namespace cambench::usecases
