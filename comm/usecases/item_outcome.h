#pragma once

// The outcome of writing one item to a device, whatever the device family:
// the one vocabulary of every write report (GUI and CLI). A family's report
// (the CamCon's WriteReport, ...) holds lists of ItemOutcome<T> and is
// summed up by OutcomeTally.

#include "model/result.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace cambench::usecases {

enum class WriteState {
    Written,    // sent and acknowledged (read back when a reply was lost)
    Unchanged,  // the device already held the wanted value: nothing was sent
    Failed,     // not written; read back: the device holds what it held before
    // The write failed, yet the device now holds something else than
    // before: `actual` says what.
    ChangedThoughFailed,
    Unknown,  // the write failed and reading back failed too
    NotSent,  // not attempted: cancelled, or the line failed on an earlier item
};

// "written", "unchanged", "failed", "changed though the write failed",
// "state unknown", "not sent".
QString writeStateText(WriteState state);

template <class T>
struct ItemOutcome {
    QString label;  // "program 0, output 1"; never contains a secret (user number)
    WriteState state = WriteState::NotSent;
    Error error;  // why it was not written (kind None when written or unchanged)
    // The device's value as known after the write: the wanted one when
    // written or unchanged, the value read back after a failure; empty when
    // unknown.
    std::optional<T> actual;
    // `actual` for a person: "10..90, 180..270", "\"Pusher\"", ...
    QString actualText;
    // Something a person should know besides the state: written only as
    // read back after an error reply, or an item that had changed on the
    // device since the caller read it.
    QString note;

    bool ok() const { return state == WriteState::Written || state == WriteState::Unchanged; }
};

// One line of a report, whatever the kind of item.
struct OutcomeLine {
    QString label;
    WriteState state = WriteState::NotSent;
    QString text;  // "program 0, output 1: failed: ...; the device keeps 10..90"
    Error error;   // the item's error (kind None when written or unchanged)
};

// "label: failed, the device keeps …: why (note)": one item for a person.
QString outcomeText(const QString& label, WriteState state, const QString& actualText,
                    const Error& error, const QString& note);

template <class T>
OutcomeLine outcomeLine(const ItemOutcome<T>& outcome) {
    return {
        outcome.label, outcome.state,
        outcomeText(outcome.label, outcome.state, outcome.actualText, outcome.error, outcome.note),
        outcome.error};
}

// The line of one item whose write failed, from what reading it back
// found: written after all (the error becomes a note), failed (the old
// value), changed though failed, or unknown (`readOk` false).
OutcomeLine failedWriteLine(const QString& label, const Error& error, bool readOk, bool isOld,
                            bool isWanted, const QString& actual);

// Counts and summary of the lines of one write, in the words every report uses.
class OutcomeTally {
public:
    OutcomeTally() = default;
    explicit OutcomeTally(QList<OutcomeLine> lines) : m_lines(std::move(lines)) {}

    const QList<OutcomeLine>& lines() const { return m_lines; }
    int count(WriteState state) const;
    int total() const { return int(m_lines.size()); }
    // Every item written or unchanged.
    bool complete() const;
    // The first error of an item that is not ok (kind None when complete):
    // decides the CLI's exit code.
    Error firstError() const;
    // "32 items: 3 written, 28 unchanged, 1 failed (the device keeps its old values)";
    // categories other than written and unchanged only when they occur.
    QString summary() const;

private:
    QList<OutcomeLine> m_lines;
};

}  // namespace cambench::usecases
