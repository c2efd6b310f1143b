#pragma once

#include "comm/device/motion_control.h"

#include <QDateTime>
#include <QObject>

namespace cambench {

// What a STOP on screen (StopBar) and the STOP key (StopShortcut) act on:
// one device's STOP (MotionStop) or a machine's, which stops every device
// of the machine that can move.
class StopControl : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    // Something can move: a STOP is shown.
    virtual bool available() const = 0;
    // A STOP can reach something that moves now.
    virtual bool armed() const = 0;
    // Stops, without a question; stopFinished() reports per axis or drive.
    virtual void stopAll() = 0;

    // The last STOP's report (empty before the first) and when it ended.
    const comm::MotionStopReport& lastReport() const { return m_lastReport; }
    QDateTime lastStopTime() const { return m_lastStop; }

Q_SIGNALS:
    void availabilityChanged();
    void stopStarted();
    void stopFinished(const cambench::comm::MotionStopReport& report);

protected:
    // Keeps `report` as the last one and says so (stopFinished).
    void finishStop(const comm::MotionStopReport& report) {
        m_lastReport = report;
        m_lastStop = QDateTime::currentDateTime();
        Q_EMIT stopFinished(report);
    }

private:
    comm::MotionStopReport m_lastReport;
    QDateTime m_lastStop;
};

}  // namespace cambench
