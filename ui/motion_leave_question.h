#pragma once

#include <QString>

class QWidget;

namespace cambench {

class MotionStop;

// Before quitting, disconnecting or connecting elsewhere while the device
// on the line can move (issue 27, item 7): asks the device what moves or is
// powered (briefly; "could not tell" is said as such) and, if anything does
// or it cannot tell, asks the person naming it: STOP and then go on, go on
// without stopping, or cancel. `action` is what would happen ("Quit",
// "Disconnect"). True: go on. A STOP that was not acknowledged everywhere
// keeps the line (so that STOP can be tried again) and says so.
bool askBeforeLeavingMotion(QWidget* parent, MotionStop& stop, const QString& action);

}  // namespace cambench
