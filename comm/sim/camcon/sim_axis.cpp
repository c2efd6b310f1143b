#include "sim_axis.h"

#include <cmath>
#include <utility>

namespace cambench::comm {

SimAxis::SimAxis(qint32 minPosition, qint32 maxPosition, double unitsPerSecond)
    : m_min(minPosition),
      m_max(maxPosition),
      m_unitsPerSecond(unitsPerSecond),
      m_basePosition(minPosition) {
    m_timer.start();
}

void SimAxis::setClock(Clock clock) {
    const qint32 current = position();
    m_clock = std::move(clock);
    setPosition(current);
}

qint32 SimAxis::position() const {
    if (m_shaft && span() > 0) {
        // Whole units of the turn the shaft has made; backwards wraps too.
        const double units = std::floor(m_shaft->position() / m_perTurn * double(span()));
        const qint64 offset = qint64(std::fmod(units, double(span())));
        return qint32(m_min + (offset < 0 ? offset + span() : offset));
    }
    if (!m_running || span() <= 0) return m_basePosition;
    const double travelled = m_unitsPerSecond * double(now() - m_baseMs) / 1000.0;
    const qint64 offset = (qint64(m_basePosition) - m_min + qint64(std::floor(travelled))) % span();
    return qint32(m_min + (offset < 0 ? offset + span() : offset));
}

double SimAxis::unitsPerSecond() const {
    if (!m_running) return 0.0;
    if (m_shaft) return std::abs(m_shaft->velocity()) / m_perTurn * double(span());
    return m_unitsPerSecond;
}

void SimAxis::follow(std::shared_ptr<const SimShaft> shaft, double perTurn) {
    m_shaft = std::move(shaft);
    m_perTurn = perTurn;
}

double SimAxis::rpm() const {
    return span() > 0 ? unitsPerSecond() * 60.0 / double(span()) : 0.0;
}

void SimAxis::setRunning(bool running) {
    const qint32 current = position();
    m_running = running;
    setPosition(current);
}

void SimAxis::setPosition(qint32 position) {
    m_basePosition = position;
    m_baseMs = now();
}

}  // namespace cambench::comm
