#pragma once

// Everything a device holds, as one project: identity, settings, every
// program (cams and name), dead times, output names, users and PLC
// networks, read with one progress. Each part gets its read time in
// Project::readAt; a part this protocol cannot reach (users on the table
// interface, ...) stays "not read" and is listed in ReadEverything::skipped.

#include "comm/usecases/use_case_progress.h"

#include "comm/camcon/camcon_device.h"
#include "model/camcon/project_file.h"

#include <QStringList>

namespace cambench::usecases {

struct ReadEverything {
    Project project;
    // One sentence per part not read and why ("Users: users exist only in
    // the ASCII protocol ..."), and settings the firmware does not know.
    QStringList skipped;
};

// Runs inside a worker job. `device` as read by the caller (readInfo); it
// becomes project.device. Cancelled: Error::cancelled(), nothing returned.
Result<ReadEverything> readEverything(comm::CamConDevice& connection, const DeviceInfo& device,
                                      const UseCaseProgress& progress = {});

// The networks per PLC area (O, P, M, X) the settings give, for reading
// and checking PLC networks: plcOutputs, inputCount, plcFlags, plcXFlags.
QMap<int, int> plcNetworkCounts(const SystemSettings& settings);

}  // namespace cambench::usecases
