#pragma once

#include "comm/device/motion_control.h"

namespace cambench::comm {

class Mc1Controller;

// STOP of every axis of an MC200 V2, for the shell and `mc axis all stop`.
// Every existing axis gets its stop telegram (AXIS_NODATA 09, the maximum
// ramp) back to back, one attempt each and no status read between; the
// stops whose answer was lost are then sent again (a stop may be repeated:
// mc1AxisRetry), and only then is each axis read back. A stop the
// controller acknowledged stays acknowledged whatever its read-back says.
class Mc1AxisMotion : public MotionControl {
public:
    explicit Mc1AxisMotion(Mc1Controller& controller) : m_controller(controller) {}

    MotionStopReport stopAllMotion() override;
    Result<QStringList> activeMotion() override;

private:
    Mc1Controller& m_controller;
};

}  // namespace cambench::comm
