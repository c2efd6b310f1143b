#pragma once

#include <QtGlobal>

namespace cambench::comm {

// How fast bytes cross the line, from which every per-attempt timeout is
// derived: a reply cannot arrive before the request and the reply have
// crossed the wire, and the device needs some time to turn around.
struct LineTiming {
    int baud = 9600;
    int bitsPerByte = 10;     // start + 8 data + stop; 11 with a parity bit
    int turnaroundMs = 100;   // the device's time to answer, plus OS and USB latency
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
};

}  // namespace cambench::comm
