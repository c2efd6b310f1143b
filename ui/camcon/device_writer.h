#pragma once

#include "model/camcon/workspace_item.h"
#include "write_plan_builder.h"

#include "comm/camcon/usecases/write_report.h"
#include "model/result.h"

#include <QList>
#include <QMetaType>

#include <functional>

class QObject;
class QWidget;

namespace cambench {

class DeviceSession;
class Workspace;

using WriteResult = Result<usecases::WriteReport>;

// Makes the workspace's device copy what the report says the device holds,
// item by item, each outcome found by the key of its item. Edits are never
// touched: an item that failed stays edited, with its undo history. An item
// of the plan the report says nothing of is added to it as not sent.
void applyWriteReport(Workspace& workspace, const PlannedWrite& planned,
                      usecases::WriteReport& report);

// The one write of the GUI: `items` (all differing ones when empty) go
// through usecases::writeItems in one job. The connected device's identity
// is read in the same job, so the plan is checked against the device on
// the line, not against what the workspace was made for; nothing is sent
// when it does not fit. The report is applied to the workspace before
// `done` gets it.
quint64 writeToDevice(QObject* context, DeviceSession* session, Workspace* workspace,
                      const QList<WorkspaceItem>& items,
                      std::function<void(const WriteResult&)> done);

// For a person: one line for the status bar ...
QString writeSummary(const WriteResult& result);
// ... and, when not everything was written, a dialog that lists every item
// not written with what the device holds now.
void presentWriteResult(QWidget* parent, DeviceSession* session, const QString& title,
                        const WriteResult& result);
// The lines that dialog lists (items not written first).
QString writeDetails(const WriteResult& result);

}  // namespace cambench

Q_DECLARE_METATYPE(cambench::usecases::WriteReport)
