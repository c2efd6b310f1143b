#pragma once

#include "model/result.h"

#include <QCoreApplication>
#include <QString>

#include <optional>

class QTextDocument;

namespace cambench {

class Workspace;

// The printable commissioning report: device identity, settings, dead
// times, and each program's cam diagram and table. Built as a text
// document (also for tests) and printed into a PDF with QPdfWriter.
class CommissioningReport {
    Q_DECLARE_TR_FUNCTIONS(cambench::CommissioningReport)
public:
    struct Options {
        // With a speed (in the axis unit: 1/min rotary, pos/s linear), each
        // program gets a table of where its outputs switch at that speed.
        std::optional<double> timingSpeed;
        // Before the names of its pictures in the document (a machine's
        // report holds several devices' reports).
        QString resourcePrefix;
    };
    static void build(QTextDocument& document, const Workspace& workspace,
                      const Options& options = {});
    static Status write(const QString& path, const Workspace& workspace,
                        const Options& options = {});
    // The report as HTML, its pictures added to `document` (a machine's
    // report takes it as the CamCon's section).
    static QString html(QTextDocument& document, const Workspace& workspace,
                        const Options& options = {});
};

}  // namespace cambench
