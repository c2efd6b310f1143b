#pragma once

#include "model/camcon/project_file.h"

namespace cambench {

class Workspace;

// The workspace's edited state as a project (model/project_file.h), and
// back. Loading a project makes everything "edited, not on the device".
Project projectFromWorkspace(const Workspace& workspace);
void loadProjectIntoWorkspace(Workspace& workspace, const Project& project);

// A new, empty project for a device with these capacities.
Project emptyProject(const DeviceInfo& capacities);

}  // namespace cambench
