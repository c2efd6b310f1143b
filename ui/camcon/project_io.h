#pragma once

#include "model/camcon/project_file.h"

namespace cambench {

class Workspace;

// The workspace as a project (model/camcon/project_file.h): every program
// it holds (read from the device or edited; a program neither read nor
// edited is absent, i.e. "not read"), names, dead times, settings, users
// and PLC networks, with the read times of the parts that are still what
// the device held (a part with edits gets none: its content is the PC's).
Project projectFromWorkspace(const Workspace& workspace);

// A new, empty project for a device with these capacities.
Project emptyProject(const DeviceInfo& capacities);

}  // namespace cambench
