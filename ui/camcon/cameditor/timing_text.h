#pragma once

#include "model/camcon/cam_timing.h"

#include <QString>

namespace cambench {

// The timing model's numbers and warnings for a person, in the user's
// language and number format (the CLI keeps model/'s English texts).

// "412 1/min", "35.5 pos/s" from positions per second.
QString speedText(double positionsPerSecond, const Axis& axis);
// "12.5 ms", "2.22 s".
QString durationText(double milliseconds);
// "Output 4: cams 2 and 3 merge above 412 1/min."
QString timingProblemText(int output, const TimingProblem& problem, const Axis& axis);

}  // namespace cambench
