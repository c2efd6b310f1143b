#pragma once

// What writeItems() did, item by item, and the device's real state after a
// failure. Parallel to the plan: report.tracks[i] is the outcome of
// plan.tracks[i], and so on.

#include "write_plan.h"

#include "model/result.h"

#include <QList>
#include <QString>
#include <QStringList>

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
    QString label;  // "program 0, output 1"; never contains a user number
    WriteState state = WriteState::NotSent;
    Error error;  // why it was not written (kind None when written or unchanged)
    // The device's value as known after the write: the wanted one when
    // written or unchanged, the value read back after a failure; empty when
    // unknown.
    std::optional<T> actual;
    // `actual` for a person: "10..90, 180..270", "\"Pusher\"", ...
    QString actualText;
    // Something a person should know besides the state: written only as
    // read back after an error reply, or a track that had changed on the
    // device since the caller read it.
    QString note;

    bool ok() const { return state == WriteState::Written || state == WriteState::Unchanged; }
};

// One line of a report, whatever the kind of item.
struct OutcomeLine {
    QString label;
    WriteState state;
    QString text;  // "program 0, output 1: failed: ...; the device keeps 10..90"
};

struct WriteReport {
    QList<ItemOutcome<SystemSettings>> settings;
    QList<ItemOutcome<QString>> programNames;
    QList<ItemOutcome<Track>> tracks;
    QList<ItemOutcome<qint32>> deadTimes;
    QList<ItemOutcome<QString>> outputNames;
    // `actual`: the user as on the device after the write, empty when the
    // device has no such user (deleted, or never created).
    QList<ItemOutcome<std::optional<User>>> users;
    QList<ItemOutcome<PlcNetwork>> plcNetworks;

    int count(WriteState state) const;
    int total() const;
    // Every item written or unchanged.
    bool complete() const;
    // The first error of an item that is not ok (kind None when complete):
    // decides the CLI's exit code.
    Error firstError() const;

    // Every item, in plan order.
    QList<OutcomeLine> lines() const;
    // "32 items: 3 written, 28 unchanged, 1 failed (the device keeps its old values)";
    // categories other than written and unchanged only when they occur.
    QString summary() const;
};

}  // namespace cambench::usecases
