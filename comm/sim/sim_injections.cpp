#include "sim_injections.h"

#include <algorithm>

namespace cambench::comm {

int SimInjections::count(char kind, const QByteArray& name) const {
    return int(std::count_if(m_received.cbegin(), m_received.cend(),
                             [&](const Received& r) { return r.kind == kind && r.name == name; }));
}

int SimInjections::commands() const {
    return int(std::count_if(m_received.cbegin(), m_received.cend(),
                             [](const Received& r) { return r.kind == '!'; }));
}

void SimInjections::setDead(int device, bool dead) {
    if (dead)
        m_dead.insert(device);
    else
        m_dead.remove(device);
}

void SimInjections::refuse(int device, char kind, const QByteArray& name, qint32 code, int skip) {
    m_refusals.append({device, kind, name, code, skip});
}

void SimInjections::record(int device, char kind, const QByteArray& name) {
    if (m_logging) m_received.append({device, kind, name});
}

std::optional<qint32> SimInjections::takeRefusal(int device, char kind, const QByteArray& name) {
    for (int i = 0; i < m_refusals.size(); ++i) {
        Refusal& refusal = m_refusals[i];
        if (refusal.device != device || refusal.kind != kind || refusal.name != name) continue;
        if (refusal.skip > 0) {
            --refusal.skip;
            return std::nullopt;
        }
        const qint32 code = refusal.code;
        m_refusals.removeAt(i);
        return code;
    }
    return std::nullopt;
}

}  // namespace cambench::comm
