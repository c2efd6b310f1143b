#pragma once

#include <QElapsedTimer>

#include <functional>

namespace cambench::comm {

// The simulated rotary axis: the actual value advances with time at a fixed
// speed and wraps from the maximum to the minimum. Stopped while the device
// is erased.
class SimAxis {
public:
    using Clock = std::function<qint64()>;  // milliseconds, monotonic

    SimAxis(qint32 minPosition, qint32 maxPosition, double unitsPerSecond);

    // Tests drive time themselves.
    void setClock(Clock clock);

    qint32 position() const;
    // Revolutions per minute, for the formatted speed display.
    double rpm() const;
    double unitsPerSecond() const { return m_running ? m_unitsPerSecond : 0.0; }

    bool running() const { return m_running; }
    void setRunning(bool running);
    void setPosition(qint32 position);

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
};

}  // namespace cambench::comm
