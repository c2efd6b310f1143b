#pragma once

#include "model/result.h"

#include <QCoreApplication>
#include <QString>

class QTextDocument;

namespace cambench {

class Workspace;

// The printable commissioning report: device identity, settings, dead
// times, and each program's cam diagram and table. Built as a text
// document (also for tests) and printed into a PDF with QPdfWriter.
class CommissioningReport {
    Q_DECLARE_TR_FUNCTIONS(cambench::CommissioningReport)
public:
    static void build(QTextDocument& document, const Workspace& workspace);
    static Status write(const QString& path, const Workspace& workspace);
};

}  // namespace cambench
