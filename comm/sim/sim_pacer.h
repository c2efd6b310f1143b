#pragma once

#include "sim_output.h"

#include <QByteArray>
#include <QList>

#include <optional>

namespace cambench::comm {

// A reply on its way to the PC: its bytes trickle out from `startUs` on.
struct PacedReply {
    QByteArray bytes;
    qint64 startUs = 0;
    int baud = 0;  // 0 = all bytes at once (no throttle)
    int bitsPerByte = 10;

    // Bytes completely received by `nowUs`.
    int bytesDueAt(qint64 nowUs) const;
    // When byte number `count` (1-based) is completely received.
    qint64 dueUs(int count) const;
    qint64 endUs() const { return dueUs(int(bytes.size())); }
};

// Serial timing at a baud rate with 10 bits per byte (8N1: start, 8 data,
// stop; 11 with a parity bit): a request of N bytes takes N*10/baud s to
// arrive, the device then works for the reply's delay, and the reply's M
// bytes follow at 10/baud s each. Each direction is one line: a reply waits
// for the one before it.
class SimPacer {
public:
    explicit SimPacer(int baud = 9600, bool throttle = true, int bitsPerByte = 10);

    int baud() const { return m_baud; }
    int bitsPerByte() const { return m_bitsPerByte; }
    bool throttled() const { return m_throttle; }

    // Time on the line for `bytes` bytes; 0 without throttle.
    qint64 transferUs(qint64 bytes) const;

    // The replies to a request whose first byte is written at `sentUs`.
    QList<PacedReply> schedule(qint64 sentUs, int requestBytes, const QList<SimOutput>& outputs);

    void reset() { m_toDeviceFreeUs = m_toPcFreeUs = 0; }

private:
    int m_baud;
    bool m_throttle;
    int m_bitsPerByte;
    qint64 m_toDeviceFreeUs = 0;
    qint64 m_toPcFreeUs = 0;
};

// Replies in flight, read off in order as their bytes arrive.
class PacedQueue {
public:
    void append(const QList<PacedReply>& replies) { m_replies += replies; }
    // Every byte received by `nowUs` and not taken yet.
    QByteArray takeDue(qint64 nowUs);
    // When the next byte arrives; nullopt when nothing is in flight.
    std::optional<qint64> nextDueUs() const;
    void clear();

private:
    QList<PacedReply> m_replies;
    int m_taken = 0;  // bytes of the first reply already taken
};

}  // namespace cambench::comm
