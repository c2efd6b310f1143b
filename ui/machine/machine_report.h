#pragma once

#include "model/result.h"

#include <QCoreApplication>

class QTextDocument;

namespace cambench {

class Machine;

// File → Machine report…: one PDF of the whole machine. First its summary
// (name, file, when, each device: family, port, line, identity, edits not
// written), then each device's section: its identity, when its line last
// answered, its edits not written, and its family's own report (the
// CamCon's commissioning report) where the family has one.
class MachineReport {
    Q_DECLARE_TR_FUNCTIONS(cambench::MachineReport)
public:
    static void build(QTextDocument& document, const Machine& machine);
    static Status write(const QString& path, const Machine& machine);
};

}  // namespace cambench
