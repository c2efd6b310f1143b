#pragma once

#include <QString>

namespace cambench::comm {

// What an error number of the device means (manual 4.6.1) and what to do,
// as complete sentences in English (translated through the "DeviceErrors"
// context when a translator is installed). Where the manual gives no
// meaning (-1 is listed only as "unknown error", other numbers not at all)
// the text says so with the number.
QString deviceErrorText(qint32 code);

// Whether the manual gives `code` a meaning of its own (-1 "unknown error"
// does not count).
bool manualExplains(qint32 code);

}  // namespace cambench::comm
