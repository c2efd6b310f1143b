#pragma once

// The one write path of CamBench, for the GUI and the CLI alike.
//
//  1. Before the first byte: the plan is checked against the connected
//     device (plan_check.h). A plan that does not fit, or holds values the
//     validation knows to be invalid, is refused as a whole (InvalidData,
//     nothing sent).
//  2. Items are written in plan order (see WritePlan). An item whose wanted
//     value equals the believed device value is not sent (Unchanged). An
//     item without a belief is read first. Tracks are always read first and
//     only the differing cams are sent, ordered so that a refused step
//     leaves the track as it was where the protocol allows.
//  3. After any failure the item is read back and its state reported as
//     it is (Failed / ChangedThoughFailed / Unknown, with the real value).
//     After a communication failure that even the read-back cannot pass,
//     or a cancel, the remaining items are NotSent.

#include "comm/usecases/use_case_progress.h"
#include "write_report.h"

#include "comm/camcon/camcon_device.h"

namespace cambench::usecases {

// Runs inside a worker job. `device` is the connected device's identity and
// capacities as read by the caller (readInfo). An Error only when nothing
// was written: the plan was refused, or a read the check needs failed.
Result<WriteReport> writeItems(comm::CamConDevice& connection, const DeviceInfo& device,
                               const WritePlan& plan, const UseCaseProgress& progress = {});

}  // namespace cambench::usecases
