#include "compax3_page.h"

#include "ui/device_session.h"

namespace cambench {

bool Compax3Page::pollStatus(std::function<void(const comm::Compax3DriveStatus&)> show) {
    if (!facts().known) return false;
    session()->run<comm::Compax3Device, comm::Compax3DriveStatus>(
        this, tr("Read drive status"),
        [](comm::Compax3Device& device, comm::JobContext&) { return device.status(); },
        [this, show = std::move(show)](Result<comm::Compax3DriveStatus> status) {
            pollAnswered(status.ok());
            if (status) show(*status);
        },
        comm::JobPriority::Poll, QStringLiteral("compax3-status"));
    return true;
}

}  // namespace cambench
