#pragma once

// The check before the first byte: does the plan fit the connected device
// (outputs, programs, positions IMIN..IMAX, cams per track, dead-time
// maximum, PLC counts, ...) and is every value valid (no overlapping cams,
// no duplicate user numbers, ...)? Pure: reads nothing from the device.

#include "write_plan.h"

#include "model/camcon/device_info.h"
#include "model/result.h"

#include <QList>
#include <QSet>
#include <QString>
#include <QStringList>

namespace cambench::usecases {

struct PlanCheck {
    QStringList problems;  // one complete sentence per problem
    // What does not exist on the device, for the summary line.
    QSet<int> missingOutputs;   // 1-based
    QSet<int> missingPrograms;  // 0-based
    int pointsOutOfRange = 0;   // cam points outside IMIN..IMAX

    bool fits() const { return problems.isEmpty(); }
    // InvalidData: one summary line ("The write was refused before anything
    // was sent: outputs 33..96 do not exist on the device (it has 1..32); 212
    // cam points lie outside 0..359; 3 further problems."), then up to
    // `listed` problems, one a line, and "and N more".
    Error refusal(const DeviceInfo& device, int listed = 10) const;
};

// The values the check needs beyond the plan and the device's identity.
struct CheckContext {
    bool rotary = true;  // the axis type the cams are checked for
    // Networks per PLC area on the device (plcOutputs, inputCount,
    // plcFlags, plcXFlags); an area missing here is not checked.
    QMap<int, int> plcNetworksPerArea;
    // The device's users before the write (for duplicate numbers and users
    // without a number); empty = none.
    QList<User> usersOnDevice;
};

PlanCheck checkPlan(const WritePlan& plan, const DeviceInfo& device, const CheckContext& context);

// "33..96", "1, 5, 9..12": numbers as ranges, ascending.
QString numberRanges(const QSet<int>& numbers);

}  // namespace cambench::usecases
