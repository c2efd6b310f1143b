#pragma once

// Reading program N of a CamCon: the one place that checks N against the
// device's programs (nothing is sent for a program the device does not
// have, and the refusal always reads the same) and reads every output's
// cams. The GUI's cam editor and Compare programs, and cambench-cli's
// cams read, diff, timing and short commands all go through here.

#include "comm/usecases/use_case_progress.h"

#include "comm/camcon/camcon_device.h"

namespace cambench::usecases {

// Success when `device` has program `number` (programs count from 0, as the
// device shows them); otherwise a Usage error that says which programs it
// has and to choose one of those.
Status checkProgramNumber(int number, const DeviceInfo& device);

// Program `number` of the connected device, whose identity the caller
// holds (`device`: its programs and outputs): every output's cams, the
// program's number set, and its name where the protocol has names (the
// device's readProgram reads it: nobody asks for it a second time). A
// number outside the device's programs sends nothing.
Result<CamProgram> readProgram(comm::CamConDevice& connection, const DeviceInfo& device, int number,
                               const UseCaseProgress& progress = {});

// The same for a caller that holds no identity yet: it is read first
// (readInfo) and returned with the program.
struct ProgramRead {
    DeviceInfo device;
    CamProgram program;
};
Result<ProgramRead> readIdentityAndProgram(comm::CamConDevice& connection, int number,
                                           const UseCaseProgress& progress = {});

}  // namespace cambench::usecases
