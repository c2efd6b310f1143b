#pragma once

#include "model/result.h"

#include <QMetaType>
#include <QString>
#include <QStringList>

namespace cambench {

// The outcome of writing one item inside a job (error kind None = written).
struct ItemOutcome {
    QString key;
    QString item;  // for the report: "Output 3 dead time"
    Error error;
};
using ItemOutcomes = QList<ItemOutcome>;

// What a write or restore did, item by item: the user is told how many items
// were written, left alone because they already matched, and failed, and is
// never told "done" when something was skipped.
struct WriteReport {
    int written = 0;
    int unchanged = 0;
    int failed = 0;
    QStringList failures;  // one sentence per failed item: which and why

    void addWritten() { ++written; }
    void addUnchanged() { ++unchanged; }
    void addFailure(const QString& item, const Error& error);
    void merge(const WriteReport& other);
    void add(const ItemOutcomes& outcomes);

    bool complete() const { return failed == 0; }
    // One line for the status bar: "3 written, 1 unchanged, 0 failed".
    QString summary() const;
    // The summary plus every failure, for a message box.
    QString details() const;
};

}  // namespace cambench

Q_DECLARE_METATYPE(cambench::WriteReport)
