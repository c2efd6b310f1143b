#pragma once

// Help -> Check this device...: the verdicts of `check` (issue 29) in a
// dialog, with Save... for the report a technician sends back.

#include "comm/usecases/device_check.h"

class QWidget;

namespace cambench {

class DeviceSession;

// Runs the check of the connected device's family through the worker and
// shows its verdicts when it is done (or why it could not run).
void runDeviceCheck(DeviceSession* session, QWidget* parent);

// The dialog of one report: the tally above, one verdict a line below,
// Save... writes the report as JSON.
void presentCheckReport(QWidget* parent, const usecases::CheckReport& report);

}  // namespace cambench
