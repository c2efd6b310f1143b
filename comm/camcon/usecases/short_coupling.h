#pragma once

// The writes of the S7-CP340 coupling's short commands (0x02, 0x03, 0x05,
// 0x07), each checked with its query before and after as every write is:
// unchanged values are not sent, and what the device holds afterwards is
// what the outcome says (issue 12, point 5). The CLI's `short` commands and
// the PLC coupling page both report through these.

#include "comm/usecases/item_outcome.h"

#include "model/camcon/cam_program.h"

namespace cambench::comm::table {
class ShortClient;
}

namespace cambench::usecases {

// 0x02; the note says the device status the reset left.
OutcomeLine shortResetErrors(comm::table::ShortClient& client);
// 0x03, checked with the status query 0x01.
OutcomeLine shortChangeProgram(comm::table::ShortClient& client, int program);
// 0x05 for track.output in `program`, checked with 0x04. The caller has
// checked the cams against the device (validateTrack).
OutcomeLine shortWriteTrack(comm::table::ShortClient& client, int program, const Track& track);
// 0x07, checked with 0x06; tenths of a millisecond.
OutcomeLine shortWriteDeadTime(comm::table::ShortClient& client, int output, int tenthsMs);

}  // namespace cambench::usecases
