#pragma once

// What writeItems() did, item by item, and the device's real state after a
// failure. Each outcome of a list carries the key of the item it is about
// (itemOf(), write_plan.h): whoever applies a report pairs it with the plan
// by that key, never by the place in the list.

#include "comm/usecases/item_outcome.h"
#include "write_plan.h"

#include "model/result.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <optional>
#include <utility>

namespace cambench::usecases {

template <class T>
struct KeyedOutcome : ItemOutcome<T> {
    WorkspaceItem item;
};

template <class T>
KeyedOutcome<T> keyed(const WorkspaceItem& item, ItemOutcome<T> outcome) {
    KeyedOutcome<T> result;
    static_cast<ItemOutcome<T>&>(result) = std::move(outcome);
    result.item = item;
    return result;
}

struct WriteReport {
    // The plan's settings groups without their communication settings
    // (a group of nothing else is dropped).
    QList<ItemOutcome<SystemSettings>> settings;
    QList<KeyedOutcome<QString>> programNames;
    QList<KeyedOutcome<Track>> tracks;
    QList<KeyedOutcome<qint32>> deadTimes;
    QList<KeyedOutcome<OutputDeadTime>> deadTimeModes;
    QList<KeyedOutcome<QString>> outputNames;
    // `actual`: the user as on the device after the write, empty when the
    // device has no such user (deleted, or never created).
    QList<KeyedOutcome<std::optional<User>>> users;
    QList<KeyedOutcome<PlcNetwork>> plcNetworks;
    QList<KeyedOutcome<AnalogueCamTrack>> analogueCams;
    std::optional<ItemOutcome<ProgrammingProgram>> programmingProgram;
    std::optional<ItemOutcome<bool>> eepromLock;
    bool eepromLockFirst = false;  // an unlock, written before every other item
    // The communication settings asked for by name (WritePlan::
    // linkSettingsAsked), one item each, written last.
    QList<ItemOutcome<SystemSettings>> linkSettings;
    // Those the plan held but nobody asked for, as the plan wanted them
    // (only those that differ from the device's): not sent, named in notes.
    SystemSettings linkSettingsLeftOut;
    // Things a person must know about the whole write, e.g. that the
    // device's EEPROM is locked and what was written lives in RAM only.
    QStringList notes;

    // Every item, in plan order, counted and summed up.
    OutcomeTally tally() const { return OutcomeTally(lines()); }
    int count(WriteState state) const { return tally().count(state); }
    int total() const { return tally().total(); }
    // Every item written or unchanged.
    bool complete() const { return tally().complete(); }
    // The first error of an item that is not ok (kind None when complete):
    // decides the CLI's exit code.
    Error firstError() const { return tally().firstError(); }

    // Every item, in plan order.
    QList<OutcomeLine> lines() const;
    // "32 items: 3 written, 28 unchanged, 1 failed (the device keeps its old values)";
    // categories other than written and unchanged only when they occur.
    // Followed by the notes, each on a line of its own.
    QString summary() const;
};

}  // namespace cambench::usecases
