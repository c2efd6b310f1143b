#pragma once

#include "ui/device_session.h"

#include "comm/camcon/camcon_device.h"

namespace cambench {

// A GUI job on the connected CamCon (DeviceSession::run for CamConDevice).
template <class T>
using CamConWork = DeviceSession::Work<comm::CamConDevice, T>;

template <class T>
quint64 runOnCamCon(DeviceSession* session, QObject* context, const QString& title,
                    CamConWork<T> work, std::function<void(Result<T>)> done,
                    comm::JobPriority priority = comm::JobPriority::User,
                    const QString& pollKey = {}) {
    return session->run<comm::CamConDevice, T>(context, title, std::move(work), std::move(done),
                                               priority, pollKey);
}

}  // namespace cambench
