#pragma once

#include "model/result.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace cambench::comm {

// What one stop command did on one axis or drive, for a person.
struct MotionStopLine {
    QString what;               // "Axis 2", "Drive at address 3"
    bool acknowledged = false;  // the device acknowledged the stop command
    QString detail;             // what the read-back found, or why it failed
    // Nothing was sent, because nothing there can move (a powerless drive):
    // stopped, without a command.
    bool nothingToStop = false;
    // The stop went to an axis the device was not known to have, and the
    // device said it has no such axis: nothing to stop there, no alarm.
    bool absent = false;
};

// What a STOP of everything did.
struct MotionStopReport {
    QList<MotionStopLine> lines;
    bool allAcknowledged() const {
        bool any = false;
        for (const MotionStopLine& line : lines) {
            if (!line.acknowledged && !line.nothingToStop && !line.absent) return false;
            any = true;
        }
        return any;
    }
};

// Implemented by the device connections of families that can move
// something (MC-1 axes, a Compax3 drive). The shell's STOP, and its question
// before disconnecting or quitting, call it without knowing the family.
class MotionControl {
public:
    virtual ~MotionControl() = default;
    // Stops everything this device can move, as fast as the line allows:
    // every stop command first, back to back, read-backs after. A stop whose
    // answer was lost is sent again (stopping twice is harmless); a stop the
    // device acknowledged is reported as acknowledged even when its
    // read-back fails afterwards.
    virtual MotionStopReport stopAllMotion() = 0;
    // What moves or is powered now, one line each ("axis 2 moves", "the
    // drive is powered"), read from the device with queries only; empty when
    // nothing does; an error when it cannot tell.
    virtual Result<QStringList> activeMotion() = 0;
};

}  // namespace cambench::comm
