#include "compax3_page.h"

namespace cambench {

bool Compax3Page::pollStatus(std::function<void(const comm::Compax3DriveStatus&)> show) {
    if (!facts().known) return false;
    runPoll<comm::Compax3Device, comm::Compax3DriveStatus>(
        tr("Read drive status"),
        [](comm::Compax3Device& device, comm::JobContext&) { return device.status(); },
        [this, show = std::move(show)](const comm::Compax3DriveStatus& status) {
            reportMotion(status.moving(), true, status.summary());  // one drive, one axis
            show(status);
        },
        QStringLiteral("compax3-status"));
    return true;
}

}  // namespace cambench
