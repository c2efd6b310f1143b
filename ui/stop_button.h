#pragma once

#include <QString>

#include <functional>

class QObject;
class QPushButton;

namespace cambench {

class MotionStop;

// A STOP button's look: big and red while it can reach the device, grey
// while disabled (a disabled STOP must never look armed).
void styleAsStop(QPushButton* button);

// A page's own STOP button (MC-1 Axes, Compax3 Motion) as one more way to
// the shell's STOP: enabled while the STOP can reach the device, pressing
// it calls MotionStop::stopAll(), and `showResult` gets every STOP's report
// (also one pressed elsewhere) while `context` lives; `armedChanged` is
// called when the STOP can reach the device or no longer can (the page
// offers its moves only while it can).
void routeToShellStop(QPushButton* button, MotionStop* stop, QObject* context,
                      std::function<void(const QString& text, bool ok)> showResult,
                      std::function<void()> armedChanged);

}  // namespace cambench
