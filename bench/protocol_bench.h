#pragma once

#include <QList>

namespace cambench::bench {

// Reads and writes one program of 32 tracks x 20 cams over every CamCon
// protocol (ASCII Standard and the table interface's two variants) at each
// baud rate of `bauds`, and prints time, wire bytes and the ratio to the
// wire limit (bytes x bits per byte / baud).
void benchProtocols(const QList<int>& bauds);

}  // namespace cambench::bench
