#pragma once

#include "model/camcon/carry_over.h"
#include "model/camcon/dead_times.h"
#include "model/camcon/device_info.h"

#include <QMap>
#include <QString>

#include <optional>

namespace cambench {

// The cam programs, program and output names and dead times of a
// workspace, as far as the workspace itself deals with them. Their holder
// is the cam editor's document (ui/camcon/cameditor/cam_document.h): every
// edit of a cam is an undo command there, and undo is a widget-side thing
// (QUndoStack is QtGui), so model/ sees that section only through this.
class CamSection {
public:
    virtual ~CamSection() = default;
    CamSection(const CamSection&) = delete;
    CamSection& operator=(const CamSection&) = delete;

    // Limits of the device (IMIN..IMAX, outputs, programs) and the axis kind.
    virtual void setLimits(const DeviceInfo& info, bool rotary) = 0;
    virtual bool isRotary() const = 0;
    // Forgets everything: edits, device copies, undo history.
    virtual void clear() = 0;
    // Another device is on the line (DeviceWorkspace::forgetDeviceCopies).
    virtual void forgetDeviceCopies(CarryOver carry) = 0;
    // Tracks, program names, output names and dead times that differ from
    // the device.
    virtual int changedCount() const = 0;

    // Output names and dead times: as shown, and the device copy.
    virtual const Names& names() const = 0;
    virtual const DeadTimes& deadTimes() const = 0;
    virtual bool outputSettingsKnown() const = 0;
    virtual std::optional<qint32> deviceDeadTime(int output) const = 0;
    virtual std::optional<QString> deviceOutputName(int output) const = 0;
    virtual int outputSettingsEditCount() const = 0;
    virtual void mergeOutputSettings(const QMap<int, QString>& outputNames,
                                     const DeadTimes& deadTimes, bool fromDevice,
                                     bool keepEdits) = 0;
    // One output's dead time that arrives alone (word 0 of its dead-time
    // mode on the table interface, read or opened): from the device it
    // becomes the device copy; the value shown takes it unless `keepEdits`
    // and the person edited it.
    virtual void mergeDeadTime(int output, qint32 deadTime, bool fromDevice, bool keepEdits) = 0;
    // The device holds `deadTime` on `output` now (a write's read-back).
    virtual void setDeviceDeadTime(int output, qint32 deadTime) = 0;
    // The person wants `deadTime` on `output` (an undo step).
    virtual void setDeadTime(int output, qint32 deadTime) = 0;

protected:
    CamSection() = default;
};

}  // namespace cambench
