#pragma once

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

}  // namespace cambench
