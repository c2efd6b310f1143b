#pragma once

#include <QByteArray>
#include <QDateTime>

namespace cambench::comm {

// One line of the traffic log. Secrets are masked by the protocol's backend
// before the entry leaves the engine.
struct TrafficEntry {
    QDateTime time;
    bool outgoing = true;
    QByteArray bytes;  // wire bytes, secrets overwritten with '*'
};

}  // namespace cambench::comm
