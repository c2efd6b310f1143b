#pragma once

#include "model/camcon/workspace_item.h"

#include "comm/camcon/usecases/write_plan.h"

#include <QList>

namespace cambench {

class Workspace;

// A write plan made from workspace items (each user write knows its row of
// Workspace::users(): UserWrite::row).
struct PlannedWrite {
    usecases::WritePlan plan;
};

// Every item of the workspace that differs from the device, in plan order.
QList<WorkspaceItem> changedItems(const Workspace& workspace);

// The plan that writes `items` (all differing ones when empty), with the
// device values the workspace believes. A track or name of a program never
// read brings the whole program: it is written as a whole (every output
// and its name), so that afterwards its device copy is known.
PlannedWrite planForItems(const Workspace& workspace, const QList<WorkspaceItem>& items);

}  // namespace cambench
