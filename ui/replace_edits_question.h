#pragma once

#include <QString>

class QWidget;

namespace cambench {

// "Read from device" on a page with `changes` unwritten edits: asks
// before the device's values replace them; true = go ahead.
bool mayReplaceEdits(QWidget* page, const QString& title, int changes);

}  // namespace cambench
