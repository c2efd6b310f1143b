#pragma once

#include "comm/device/device_connection.h"
#include "model/result.h"

#include <QCoreApplication>
#include <QString>

#include <atomic>
#include <functional>

namespace cambench::comm {

// What a running job may use: the connected device and a way to report
// progress. Passed to the job's function on the worker thread.
class JobContext {
public:
    JobContext(DeviceConnection* device, QString notConnected, const std::atomic_bool& cancel,
               std::function<void(qint64 done, qint64 total, const QString& text)> progress)
        : m_device(device),
          m_notConnected(std::move(notConnected)),
          m_cancel(cancel),
          m_progress(std::move(progress)) {}

    // The connected device, whatever its family; null when not connected.
    DeviceConnection* device() { return m_device; }

    // The connected device as the family interface a job is written for
    // (CamConDevice, ...): a Communication error when nothing is connected,
    // a Usage error when the connection reaches another family.
    template <class Family>
    Result<Family*> family() {
        if (!m_device) return Error::communication(m_notConnected);
        if (auto* device = dynamic_cast<Family*>(m_device)) return device;
        return Error::usage(
            QCoreApplication::translate("cambench::comm",
                                        "the connection speaks %1, which does not reach this "
                                        "kind of device; connect with a protocol of its family")
                .arg(m_device->protocolId()));
    }

    bool cancelled() const { return m_cancel.load(); }
    void progress(qint64 done, qint64 total, const QString& text = {}) {
        if (m_progress) m_progress(done, total, text);
    }

private:
    DeviceConnection* m_device;
    QString m_notConnected;
    const std::atomic_bool& m_cancel;
    std::function<void(qint64, qint64, const QString&)> m_progress;
};

// Urgent jobs (a STOP) are served first, also between two requests of a
// running job; user actions are served before polling (monitor) jobs.
enum class JobPriority { Urgent = 0, User = 1, Poll = 2 };

// The result of a job a STOP took from the queue before it ran: nothing of
// it reached the device.
inline Error droppedByStop() {
    return {ErrorKind::Cancelled,
            QCoreApplication::translate("cambench::comm", "not sent: dropped by STOP"), 0};
}

}  // namespace cambench::comm
