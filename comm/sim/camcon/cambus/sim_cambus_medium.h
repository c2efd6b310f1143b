#pragma once

#include "comm/camcon/cambus/cambus_station.h"

#include <QByteArray>
#include <QHash>
#include <QRandomGenerator>

#include <deque>
#include <vector>

namespace cambench::comm {

// One simulated user: its station and what it does with what the station
// received (execute a request, count an answer).
class SimCamBusUser {
public:
    virtual ~SimCamBusUser() = default;
    virtual CamBusStation& station() = 0;
    // After the station heard bytes or ran its timers.
    virtual void service(qint64 nowMs) { Q_UNUSED(nowMs); }
    // The user's own timer (a CamCon working on a request); -1 = none.
    virtual qint64 serviceTimerMs() const { return -1; }
};

// Misbehaviour of the simulated bus, from one seeded generator.
struct SimCamBusFaults {
    double damageBlock = 0.0;  // a block on the wire gets one byte changed
    double loseAck = 0.0;      // a one-byte 80+n answer is lost on the wire
    quint32 seed = 1;
};

// The wire of a simulated Cam-BUS: every byte one user writes reaches all
// the others once it has crossed the wire at the baud rate (8N1), in order.
// The simulated users are stations attached here; the PC is outside (on a
// pty, TCP or the in-process transport): what it writes comes in through
// inject() and what the simulated users write goes out through advance().
// Runs on any clock the caller gives (the tests' virtual one, the
// simulator's monotonic one).
class SimCamBusMedium {
public:
    explicit SimCamBusMedium(int baud = 38400) : m_baud(baud) {}

    // Not owned; each hears everything the others write.
    void attach(SimCamBusUser* user) { m_users.push_back(user); }
    void setFaults(const SimCamBusFaults& faults);

    // Bytes (P12 encoding) from the PC, which has finished sending them at `nowMs`.
    void inject(const QByteArray& encoded, qint64 nowMs);
    // Runs the users until `nowMs`: returns what they wrote (P12), for the PC.
    QByteArray advance(qint64 nowMs);
    qint64 nextTimerMs() const;

    struct Counters {
        int damagedBlocks = 0;
        int lostAcks = 0;
    };
    const Counters& counters() const { return m_counters; }

private:
    struct InFlight {
        qint64 atMs = 0;   // crossed the wire then
        QByteArray bytes;  // one character (P12 encoding) or one break
        int from = -1;     // index into m_users; -1: the PC
    };
    QByteArray applyFaults(QByteArray encoded);
    void deliver(const InFlight& piece, qint64 nowMs);
    void put(int from, const QByteArray& bytes, qint64 nowMs);
    qint64 wireMs(qint64 bytes) const;

    int m_baud;
    std::vector<SimCamBusUser*> m_users;
    std::deque<InFlight> m_wire;
    SimCamBusFaults m_faults;
    QRandomGenerator m_random{1};
    Counters m_counters;
    QHash<int, qint64> m_senderFreeAt;  // -1: the PC
    qint64 m_lastAt = 0;                // the time advance() ran up to
};

}  // namespace cambench::comm
