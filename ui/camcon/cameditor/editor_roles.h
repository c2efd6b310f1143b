#pragma once

#include <QCoreApplication>
#include <QVariant>
#include <Qt>

namespace cambench {

// Item data roles the editor's models offer to RangeDelegate, so one
// delegate serves every numeric column with the limits of the device.
enum EditorRole {
    MinimumRole = Qt::UserRole + 1,  // smallest value the editor accepts
    MaximumRole,                     // largest value
    DecimalsRole,                    // decimals; absent or 0 = integer spin box
    SuffixRole,                      // unit shown in the editor, e.g. " ms"
};

// What a cell holding a time in 0.1 ms steps (dead times, minimum pulses)
// gives the delegate: the value in ms for editing, 0..`maximumMs` with one
// decimal and " ms". Other roles: empty, for the model to answer.
inline QVariant millisecondsEditData(qint32 tenths, double maximumMs, int role) {
    switch (role) {
        case Qt::EditRole:
            return tenths / 10.0;
        case Qt::TextAlignmentRole:
            return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
        case MinimumRole:
            return 0.0;
        case MaximumRole:
            return maximumMs;
        case DecimalsRole:
            return 1;
        case SuffixRole:
            return QCoreApplication::translate("cambench::TrackTableModel", " ms");
        default:
            return {};
    }
}

}  // namespace cambench
