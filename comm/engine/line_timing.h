#pragma once

#include <QtGlobal>

#include <algorithm>

namespace cambench::comm {

// How fast bytes cross the line, from which every per-attempt timeout is
// derived: a reply cannot arrive before the request and the reply have
// crossed the wire, and the device needs some time to turn around.
struct LineTiming {
    int baud = 9600;
    int bitsPerByte = 10;  // start + 8 data + stop; 11 with a parity bit
    // From the last request byte on the wire to the first reply byte at the
    // PC, beyond the wire time itself. The simulator answers after 2 ms (its
    // processing delay) plus well under 1 ms of pty or in-process delivery.
    // A real CamCon answers an ordinary command in a few ms (a 25 MHz
    // controller; ?EE and the cam searches read a serial EEPROM, ~3 ms); a
    // USB serial adapter holds short replies up to its latency timer (FTDI:
    // 16 ms); the OS scheduler adds a few ms (Windows: a 15.6 ms tick); a
    // serial device server on a LAN adds its packing delay and the round
    // trip, a few ms more. Together about 40-50 ms; 100 ms leaves twice that
    // for a device slower than we know, and a lost reply still costs only
    // ~0.1 s. Slower paths (a VPN, a radio link) need --timeout.
    int turnaroundMs = 100;
    int longWorkMs = 150000;  // the longest a device works before answering (!CA: 2 min)
    int probeAfterMs = 3000;  // silence after which a long request is probed

    // Time for `bytes` bytes on the wire, rounded up.
    int wireMs(qint64 bytes) const {
        if (baud <= 0) return 0;
        return int((bytes * bitsPerByte * 1000 + baud - 1) / baud);
    }
    // One attempt: the request out, the longest reply back, the turnaround.
    int attemptMs(qint64 requestBytes, qint64 replyBytes) const {
        return wireMs(requestBytes + replyBytes) + turnaroundMs;
    }
    // The first reply byte: the request out, the turnaround, one byte back.
    // A silent line past this is a lost reply (or a lost request); the rest
    // of a reply that has begun gets the whole attemptMs.
    int firstByteMs(qint64 requestBytes) const { return wireMs(requestBytes + 1) + turnaroundMs; }
    // Silence inside a frame after which the frame has broken off (its end
    // was damaged): a device sends a frame in one go, so only the path can
    // pause it - as long as it can delay a first byte (an adapter's latency
    // timer, a scheduler tick, a device server whose Nagle algorithm waits
    // for our delayed ACK: 40 ms on Linux). Rare (a hit CR), so the whole
    // turnaround margin costs little, and less than the whole attempt.
    int frameGapMs() const { return turnaroundMs + wireMs(4); }
};

}  // namespace cambench::comm
