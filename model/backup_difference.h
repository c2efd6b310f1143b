#pragma once

// One item that differs between two states of a device, whatever its
// family (issue 36): a backup and the device now (verify), two backups
// (diff), or the device now and the backup about to be written (the plan
// of a restore). Each family names its items in its own terms - "program
// 0, output 5", "V12", "1902.1" - and words the line ("program 0, output
// 5: cam 100–200 added", "V12 0 → 4711", "1902.1 Set 1 velocity 200 →
// 321"); the machine puts the device's name in front.

#include <QList>
#include <QString>

namespace cambench {

enum class ChangeKind {
    Added,    // only on the new side
    Removed,  // only on the old side
    Changed,  // on both, with other values
};

struct BackupDifference {
    // The machine's name of the device ("cams"); empty for a single device.
    QString device;
    // The item, stable within its family: "program 0, output 5", "V12",
    // "1902.1", "setting axisLength".
    QString key;
    // What of the item differs, in the family's words: "cam", "name",
    // "Set 1 velocity" (a Compax3 object's name); may be empty.
    QString what;
    // The old side's value (the backup in a verify, the first backup in a
    // diff, the device in a plan); empty when added.
    QString oldValue;
    // The new side's (the device in a verify, the second backup, the
    // backup in a plan); empty when removed.
    QString newValue;
    ChangeKind kind = ChangeKind::Changed;
    // The line in the family's words, without the device's name.
    QString text;

    // "cams: program 0, output 5: cam 100–200 added"; the text alone for a
    // single device.
    QString line() const;

    friend bool operator==(const BackupDifference& a, const BackupDifference& b) {
        return a.device == b.device && a.key == b.key && a.what == b.what &&
               a.oldValue == b.oldValue && a.newValue == b.newValue && a.kind == b.kind &&
               a.text == b.text;
    }
};

// "old → new", "new added", "old removed": the change part of a line.
QString changeText(ChangeKind kind, const QString& oldValue, const QString& newValue);

// The differences with `device` set on each (the machine's name for it).
QList<BackupDifference> onDevice(QList<BackupDifference> differences, const QString& device);

}  // namespace cambench
