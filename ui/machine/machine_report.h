#pragma once

#include "model/result.h"

#include <QCoreApplication>

#include <functional>

class QTextDocument;

namespace cambench {

class Machine;
class MachineProgress;
struct ReleasedChanges;

// Machine → Machine report…: one PDF of the whole machine. First its
// summary (name, file, when, each device: family, port, line, identity,
// edits not written), then each device's section: its identity, its line,
// its edits not written, and its family's own section (FamilyGui::
// reportSection: the CamCon's commissioning report, the MC-1's program,
// axes, parameter table, variables and flags, the Compax3's status, last
// error and parameter set with names), read from the device just before
// (read()). With `released`, the changes since the released version
// (machine_report_changes.h) follow the summary. Every time on the page in
// one format (reportTime).
class MachineReport {
    Q_DECLARE_TR_FUNCTIONS(cambench::MachineReport)
public:
    // Reads each connected device's part (FamilyGui::readForReport), each
    // on its own worker at once, a bar and a result line per device in
    // `progress`; `done` when every device is done. A device not on the
    // line is not read, and its line says so.
    static void read(Machine& machine, MachineProgress* progress, std::function<void()> done);
    static void build(QTextDocument& document, const Machine& machine,
                      const ReleasedChanges* released = nullptr);
    static Status write(const QString& path, const Machine& machine,
                        const ReleasedChanges* released = nullptr);
};

}  // namespace cambench
