#pragma once

namespace cambench {

// What stays of the values shown when another device answers (the person's
// answer to DeviceChangeDialog). The old device's values are that device's,
// never the person's: only what the person changed counts as an edit.
enum class CarryOver {
    Nothing,     // the new device's values: every edit goes
    Changes,     // only the items the person changed, over the new device's values
    Everything,  // a copy of the old device's values as shown, to write to the new one
};

}  // namespace cambench
