#pragma once

#include "sim_profile.h"
#include "sim_state.h"

#include <QByteArray>
#include <QList>

#include <optional>

namespace cambench::comm {

// The device's EEPROM as ?EE/!EE see it (manual 5.6, notes 6): a backup
// reads a snapshot taken at block 0000; a restore erases, collects blocks
// in ascending order and parses them when the closing empty block arrives.
class SimEeprom {
public:
    explicit SimEeprom(const SimProfile& profile) : m_profile(profile) {}

    // ?EE: block 0000 takes a fresh snapshot of `state`; a later block is
    // read from the last snapshot. nullopt past the end (:EEFFFF).
    std::optional<QByteArray> read(int number, const SimState& state);

    struct WriteOutcome {
        qint32 error = 0;                  // 0 or a device error number (-41..-46)
        bool erased = false;               // block 0000 accepted: the device is now erased
        std::optional<SimState> restored;  // closing block: the device starts with this
    };
    // !EE: one block of a restore.
    WriteOutcome write(int number, const QByteArray& data);

    bool transferring() const { return m_next > 0; }

private:
    WriteOutcome abort(qint32 error);

    const SimProfile& m_profile;
    QList<QByteArray> m_snapshot;
    QList<QByteArray> m_received;
    int m_next = 0;  // block number expected next; 0 = no transfer
};

}  // namespace cambench::comm
