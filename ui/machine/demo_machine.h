#pragma once

#include "model/machine/machine_file.h"
#include "model/result.h"

namespace cambench {

// File → Open demo machine: docs/demo-machine.json, built into the program
// (a resource): a machine of simulated devices on in-process `sim` ports,
// one of each family, for trying the machine window without hardware.
Result<MachineFile> demoMachineFile();

// A machine file from disk; the error names the file and what is wrong.
Result<MachineFile> readMachineFile(const QString& path);

}  // namespace cambench
