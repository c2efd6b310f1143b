#pragma once

#include "sim_output.h"

#include <QRandomGenerator>

#include <optional>

namespace cambench::comm {

// Misbehaviour on purpose (cf. libmodbus' unit-test server): all random
// choices come from one seeded generator, so a test sees the same faults
// on every run.
struct SimFaultSettings {
    double corruptProbability = 0.0;  // one byte of a reply changed (3964R: the BCC of its block)
    double dropProbability = 0.0;     // a reply never sent, the request executed (a lost reply)
    double ignoreProbability = 0.0;   // a request not executed, as if it arrived damaged
    QByteArray dropFirstReplyTo;      // lead + body start: the first reply to it is lost
    // 3964R only (SimTableLine), each per chance:
    double nakProbability = 0.0;        // a good block answered NAK, not executed
    double lostDleProbability = 0.0;    // the device's DLE lost on the line
    double collisionProbability = 0.0;  // the device's STX crosses the PC's; the device yields
    int extraDelayMs = 0;               // added to every reply
    bool dead = false;                  // never answers
    quint32 seed = 1;
};

struct SimFaultCounters {
    int replies = 0;  // replies offered to the injector
    int corrupted = 0;
    int dropped = 0;  // by chance or because the device is dead
    int ignored = 0;  // requests not executed
};

class SimFaults {
public:
    explicit SimFaults(const SimFaultSettings& settings = {});

    const SimFaultSettings& settings() const { return m_settings; }
    const SimFaultCounters& counters() const { return m_counters; }

    // Whether the device misses this request (it arrived damaged).
    bool ignoresRequest();
    // The reply to `request` (lead + body) as it reaches the line; nullopt
    // when it is lost.
    std::optional<SimOutput> apply(SimOutput output, QByteArrayView request = {});

private:
    SimFaultSettings m_settings;
    SimFaultCounters m_counters;
    QRandomGenerator m_random;
    bool m_droppedFirst = false;
};

}  // namespace cambench::comm
