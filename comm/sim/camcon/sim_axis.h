#pragma once

#include "comm/sim/sim_shaft.h"

#include <QElapsedTimer>

#include <functional>
#include <memory>

namespace cambench::comm {

// The simulated rotary axis: the actual value advances with time at a fixed
// speed and wraps from the maximum to the minimum. Stopped while the device
// is erased. On a simulated machine's shaft it turns with the shaft instead.
class SimAxis {
public:
    using Clock = std::function<qint64()>;  // milliseconds, monotonic

    SimAxis(qint32 minPosition, qint32 maxPosition, double unitsPerSecond);

    // Tests drive time themselves.
    void setClock(Clock clock);

    qint32 position() const;
    // Revolutions per minute, for the formatted speed display.
    double rpm() const;
    double unitsPerSecond() const;

    bool running() const { return m_running; }
    void setRunning(bool running);
    void setPosition(qint32 position);

    // From now on the position follows `shaft` (its own motion yields):
    // `perTurn` shaft units turn it once through min..max, shaft position 0
    // being the minimum; a standing shaft holds it.
    void follow(std::shared_ptr<const SimShaft> shaft, double perTurn);

private:
    qint64 now() const { return m_clock ? m_clock() : m_timer.elapsed(); }
    qint64 span() const { return qint64(m_max) - m_min + 1; }

    qint32 m_min;
    qint32 m_max;
    double m_unitsPerSecond;
    bool m_running = true;
    Clock m_clock;
    QElapsedTimer m_timer;
    qint64 m_baseMs = 0;
    qint32 m_basePosition;
    std::shared_ptr<const SimShaft> m_shaft;
    double m_perTurn = kSimShaftPerTurn;
};

}  // namespace cambench::comm
