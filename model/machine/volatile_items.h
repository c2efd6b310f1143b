#pragma once

// The items of a device that change by themselves (issue 37): a machine
// file names them per device, `"volatile": ["V100-V199", "V12"]`, and no
// comparison of the machine's history - a version with the one before,
// the devices now with the released version - counts them as a
// difference. An item is named as its family's comparison names it (a
// difference's key: "V12", "1902.1"); a range "V100-V199" (or "V100-199")
// takes every key of the same text before the number and a number within
// it. Names no family.

#include "model/result.h"

#include <QString>
#include <QStringList>

namespace cambench {

// Whether `key` is among `items`.
bool isVolatileItem(const QStringList& items, const QString& key);

// An item that is empty, or a range whose end is below its start, is
// refused; `where` names the device in the message.
Status checkVolatileItems(const QStringList& items, const QString& where);

}  // namespace cambench
