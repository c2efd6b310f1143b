#pragma once

#include "comm/camcon/ascii/frame.h"
#include "model/result.h"

#include <QByteArray>

namespace cambench::comm {

// What a Cam-BUS block carries (P7): one CamCon ASCII frame (docs/protocols/camcon-ascii.md) with
// its two checksum characters, without CR LF and without ESC (manual §4.4: the escapes belong to
// the Standard and Multiuser framings only).
QByteArray camBusPayload(char lead, QByteArrayView body);

// The frame in a block's data: its lead and body, the checksum checked; an
// InvalidData error that says what is wrong otherwise.
Result<Frame> parseCamBusPayload(const QByteArray& data);

}  // namespace cambench::comm
