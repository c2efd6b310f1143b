#include "sim_eeprom.h"

#include "comm/sim/sim_log.h"
#include "sim_cam_store.h"
#include "sim_eeprom_format.h"

namespace cambench::comm {

std::optional<QByteArray> SimEeprom::read(int number, const SimState& state) {
    if (number == 0 || m_snapshot.isEmpty()) m_snapshot = sim_eeprom::serialize(state, m_profile);
    if (number < 0 || number >= m_snapshot.size()) return std::nullopt;
    return m_snapshot.at(number);
}

SimEeprom::WriteOutcome SimEeprom::abort(qint32 error) {
    m_received.clear();
    m_next = 0;
    WriteOutcome outcome;
    outcome.error = error;
    return outcome;
}

SimEeprom::WriteOutcome SimEeprom::write(int number, const QByteArray& data) {
    if (number == 0) {
        if (data.size() != sim_eeprom::kBasicBlockBytes) return abort(sim_errors::kBlockZeroLength);
        if (m_profile.eraseFails) return abort(sim_errors::kEraseFailed);
        m_received = {data};
        m_next = 1;
        WriteOutcome outcome;
        outcome.erased = true;
        return outcome;
    }
    if (!transferring()) return abort(sim_errors::kIncomplete);
    if (number != m_next) return abort(sim_errors::kBlockOrder);
    if (data.isEmpty()) {
        Result<SimState> state = sim_eeprom::parse(m_received, m_profile);
        if (!state) {
            qCWarning(commSimLog) << "restore cannot start:" << state.error().message;
            return abort(sim_errors::kStartFailed);
        }
        WriteOutcome outcome = abort(0);
        outcome.restored = std::move(state).value();
        return outcome;
    }
    if (sim_eeprom::blockLength(quint8(data.at(0))) != data.size())
        return abort(sim_errors::kBlockLength);
    m_received.append(data);
    ++m_next;
    return {};
}

}  // namespace cambench::comm
