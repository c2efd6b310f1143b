#include "sim_mc1_line.h"

#include "comm/mc1/mc1_telegram.h"

namespace cambench::comm {

namespace {
constexpr int kCharacterTimeoutMs = 100;
}  // namespace

QList<SimOutput> SimMc1Line::receive(QByteArrayView bytes, qint64 nowMs) {
    QList<SimOutput> out;
    m_pending.append(bytes.toByteArray());
    while (!m_pending.isEmpty()) {
        const int length = m_controller.requestLength(m_pending);
        if (length < 0) {
            m_pending.clear();
            out << SimOutput{QByteArray(1, char(kMc1Nak)), 0};
            break;
        }
        if (length == 0 || m_pending.size() < length) break;
        const QByteArray telegram = m_pending.left(length);
        m_pending.remove(0, length);
        if (m_faults.settings().dead || m_faults.ignoresRequest()) continue;
        const QByteArray answer = m_controller.handle(telegram, nowMs);
        if (answer.isEmpty()) continue;
        if (std::optional<SimOutput> sent = m_faults.apply(SimOutput{answer, 0}, telegram))
            out << *sent;
    }
    m_deadline = nowMs + kCharacterTimeoutMs;
    return out;
}

QList<SimOutput> SimMc1Line::poll(qint64 nowMs) {
    if (m_pending.isEmpty() || nowMs < m_deadline) return {};
    m_pending.clear();
    return {SimOutput{QByteArray(1, char(kMc1Nak)), 0}};
}

QString SimMc1Line::protocolName() const {
    return QStringLiteral("MC-1 (%1)").arg(mc1VariantName(m_controller.variant()));
}

}  // namespace cambench::comm
