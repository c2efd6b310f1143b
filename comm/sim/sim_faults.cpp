#include "sim_faults.h"

namespace cambench::comm {

SimFaults::SimFaults(const SimFaultSettings& settings)
    : m_settings(settings), m_random(settings.seed) {}

bool SimFaults::ignoresRequest() {
    // Drawn only when asked for, so that the replies' faults of a seed stay
    // the same without it.
    if (m_settings.ignoreProbability <= 0.0) return false;
    if (m_random.generateDouble() >= m_settings.ignoreProbability) return false;
    ++m_counters.ignored;
    return true;
}

std::optional<SimOutput> SimFaults::apply(SimOutput output, QByteArrayView request) {
    ++m_counters.replies;
    // Draw both numbers for every reply so that one setting does not shift
    // the random sequence of the other.
    const double dropDraw = m_random.generateDouble();
    const double corruptDraw = m_random.generateDouble();
    const bool dropFirst = !m_droppedFirst && !m_settings.dropFirstReplyTo.isEmpty() &&
                           request.startsWith(m_settings.dropFirstReplyTo);
    if (dropFirst) m_droppedFirst = true;
    if (m_settings.dead || dropFirst || dropDraw < m_settings.dropProbability) {
        ++m_counters.dropped;
        return std::nullopt;
    }
    if (corruptDraw < m_settings.corruptProbability && !output.bytes.isEmpty()) {
        const int index = int(m_random.bounded(qint64(output.bytes.size())));
        const char mask = char(1 + m_random.bounded(255));  // never 0: the byte really changes
        output.bytes[index] = char(output.bytes.at(index) ^ mask);
        ++m_counters.corrupted;
    }
    output.delayMs += m_settings.extraDelayMs;
    return output;
}

}  // namespace cambench::comm
