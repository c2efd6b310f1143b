#include "sim_cambus_medium.h"

#include <algorithm>

namespace cambench::comm {

namespace {

// One character on the wire (in P12's encoding: a data FF doubled) or one
// break, with the character times it takes.
struct WireUnit {
    QByteArray encoded;
    int characters = 1;
};

// `encoded` as the wire carries it, one unit after the other. A break holds
// the line for 2 character times and leaves it idle for 2
// (docs/protocols/cambus.md).
QList<WireUnit> wireUnits(const QByteArray& encoded) {
    QByteArray pending = encoded;
    QList<WireUnit> units;
    for (const MarkedRead& read : takeBreakMarked(pending)) {
        if (read.kind == MarkedRead::Break) {
            units << WireUnit{QByteArray::fromHex("ff0000"), 4};
            continue;
        }
        for (char c : read.data) units << WireUnit{escapeBreakMarks(QByteArray(1, c)), 1};
    }
    return units;
}

bool isAck(const QByteArray& encoded) {
    return encoded.size() == 1 && camBusKind(quint8(encoded.at(0))) == CamBusByteKind::Nak;
}

// A block as one user writes it: LEN, LEN bytes, CHK1, CHK2.
bool isBlock(const QByteArray& encoded) {
    return encoded.size() >= 4 && quint8(encoded.at(0)) + 3 <= encoded.size() &&
           !encoded.contains(QByteArray::fromHex("ff0000"));
}

}  // namespace

void SimCamBusMedium::setFaults(const SimCamBusFaults& faults) {
    m_faults = faults;
    m_random.seed(faults.seed);
}

qint64 SimCamBusMedium::wireMs(qint64 bytes) const {
    const qint64 baud = std::max(1, m_baud);
    return (bytes * 10 * 1000 + baud - 1) / baud;
}

QByteArray SimCamBusMedium::applyFaults(QByteArray encoded) {
    if (m_faults.loseAck > 0 && isAck(encoded) && m_random.generateDouble() < m_faults.loseAck) {
        ++m_counters.lostAcks;
        return {};
    }
    if (m_faults.damageBlock > 0 && isBlock(encoded) &&
        m_random.generateDouble() < m_faults.damageBlock) {
        ++m_counters.damagedBlocks;
        // One data byte changed (never into FF, which P12 would have doubled).
        const int at = 1 + int(m_random.bounded(quint32(quint8(encoded.at(0)))));
        char changed = char(quint8(encoded.at(at)) ^ 0x04);
        if (quint8(changed) == 0xFF) changed = char(0xFB);
        if (quint8(encoded.at(at)) != 0xFF) encoded[at] = changed;
    }
    return encoded;
}

void SimCamBusMedium::inject(const QByteArray& encoded, qint64 nowMs) {
    const QByteArray bytes = applyFaults(encoded);
    if (bytes.isEmpty()) return;
    // The PC's bytes cross the wire like everybody's.
    put(-1, bytes, nowMs);
}

void SimCamBusMedium::put(int from, const QByteArray& bytes, qint64 nowMs) {
    // One sender's bytes follow each other; two senders' may overlap (the
    // breaks of users that start an initialisation phase at once do). What
    // was written later is never heard earlier: an answer cannot overtake
    // what it answers. Each character reaches the others once it has
    // crossed, not the whole piece at its end: a block longer than T has no
    // gap of T in it (P11), and a listener that heard only its end would
    // take the turn for over halfway through.
    qint64& free = m_senderFreeAt[from];
    const qint64 start = std::max(nowMs, free);
    qint64 characters = 0;
    for (const WireUnit& unit : wireUnits(bytes)) {
        characters += unit.characters;
        const qint64 crossed = start + wireMs(characters);
        const qint64 at = m_wire.empty() ? crossed : std::max(crossed, m_wire.back().atMs);
        m_wire.push_back(InFlight{at, unit.encoded, from});
    }
    free = start + wireMs(characters);
}

void SimCamBusMedium::deliver(const InFlight& piece, qint64 nowMs) {
    for (std::size_t i = 0; i < m_users.size(); ++i)
        if (int(i) != piece.from) m_users[i]->station().feed(piece.bytes, nowMs);
}

qint64 SimCamBusMedium::nextTimerMs() const {
    qint64 next = m_wire.empty() ? -1 : m_wire.front().atMs;
    for (const SimCamBusUser* user : m_users) {
        for (const qint64 timer :
             {const_cast<SimCamBusUser*>(user)->station().nextTimerMs(), user->serviceTimerMs()})
            if (timer >= 0 && (next < 0 || timer < next)) next = timer;
    }
    return next;
}

QByteArray SimCamBusMedium::advance(qint64 nowMs) {
    QByteArray toPc;
    // Bounded: a station whose timer does not move on cannot hang the host.
    for (int round = 0; round < 10000; ++round) {
        const qint64 next = nextTimerMs();
        if (next < 0 || next > nowMs) break;
        // A timer that fell due in the past runs now: time goes forward only.
        const qint64 at = std::max(next, m_lastAt);
        m_lastAt = at;
        bool delivered = false;
        while (!m_wire.empty() && m_wire.front().atMs <= at) {
            const InFlight piece = m_wire.front();
            m_wire.pop_front();
            deliver(piece, at);
            delivered = true;
        }
        for (SimCamBusUser* user : m_users) {
            if (const qint64 timer = user->station().nextTimerMs(); timer >= 0 && timer <= at)
                user->station().poll(at);
            user->service(at);
            // What the service queued may go at once (the user holds the token).
            user->station().poll(at);
        }
        bool wrote = false;
        for (std::size_t i = 0; i < m_users.size(); ++i) {
            const QByteArray out = m_users[i]->station().takeOutput();
            if (out.isEmpty()) continue;
            wrote = true;
            const QByteArray bytes = applyFaults(out);
            toPc += bytes;
            if (!bytes.isEmpty()) put(int(i), bytes, at);
        }
        if (!wrote && !delivered && nextTimerMs() <= next) break;
    }
    return toPc;
}

}  // namespace cambench::comm
