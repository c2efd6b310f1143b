#pragma once

#include "model/result.h"

#include <QMetaType>
#include <QString>
#include <QStringList>

class QWidget;

namespace cambench {

// The sections only the table interface has (dead-time modes, analogue
// cams) write from their own page, one RK512 write per item, not through
// usecases::writeItems: the project file and the CLI do not hold them yet.

// One edited value of such a page that differs from the device; `key`
// identifies it for the page's writeItems().
struct PageChange {
    QString key;
    QString item;  // "Output 3 dead-time mode"
    QString device;
    QString edited;
};

// The outcome of writing one item inside a job (error kind None = written).
struct PageItemOutcome {
    QString key;
    QString item;
    Error error;
};
using PageItemOutcomes = QList<PageItemOutcome>;

// What a page's write did, item by item: never "done" when something
// failed. A failed item may still have reached the device (its reply lost):
// the report says so, and the page keeps the edits rather than guess.
struct PageWriteReport {
    int written = 0;
    int unchanged = 0;
    int failed = 0;
    QStringList failures;  // one sentence per failed item: which and why
    // Items refused on the PC before anything was sent (they would not fit
    // the device): counted as failed, listed apart, as the device is untouched.
    QStringList refusals;

    void addWritten() { ++written; }
    void addUnchanged() { ++unchanged; }
    void addFailure(const QString& item, const Error& error);
    void addRefusal(const QString& item, const QString& reason);
    void add(const PageItemOutcomes& outcomes);

    bool complete() const { return failed == 0; }
    // One line for the status bar: "3 written, 0 unchanged, 1 failed".
    QString summary() const;
    // The summary plus every failure, for a message box.
    QString details() const;
};

// "Read from device" on such a page with `changes` unwritten edits: asks
// before the device's values replace them; true = go ahead.
bool mayReplaceEdits(QWidget* page, const QString& title, int changes);

}  // namespace cambench

Q_DECLARE_METATYPE(cambench::PageWriteReport)
