#pragma once

#include "model/camcon/workspace_item.h"

#include "comm/camcon/usecases/write_plan.h"

#include <QList>

namespace cambench {

class Workspace;

// A write plan made from workspace items, and what each of its users
// stands for (the plan knows users by their device number only).
struct PlannedWrite {
    usecases::WritePlan plan;
    QList<int> userIndex;  // parallel to plan.users: Workspace::users() index, -1 = deletion
};

// Every item of the workspace that differs from the device, in plan order.
QList<WorkspaceItem> changedItems(const Workspace& workspace);

// The plan that writes `items` (all differing ones when empty), with the
// device values the workspace believes. A track or name of a program never
// read brings the whole program: it is written as a whole (every output
// and its name), so that afterwards its device copy is known.
PlannedWrite planForItems(const Workspace& workspace, const QList<WorkspaceItem>& items);

}  // namespace cambench
