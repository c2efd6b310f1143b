#pragma once

class QWidget;

namespace cambench {

// Shows a top-level window at the size it was given, or maximized where
// that size would put its bottom (the status bar, the connection indicator)
// or its right edge beyond the screen: a laptop's 1366 x 768 included.
// `restored`: the size is the person's own from the last run; kept as is.
void showFitting(QWidget& window, bool restored);

}  // namespace cambench
