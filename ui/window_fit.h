#pragma once

class QWidget;

namespace cambench {

// Shows a top-level window at the size it was given, or maximized where
// that size would put its bottom (the status bar, the connection indicator)
// or its right edge beyond the screen: a laptop's 1366 x 768 included.
// `restored`: the size is the person's own from the last run; kept as is.
void showFitting(QWidget& window, bool restored);

// Resizes a window (a dialog) to `width` x `height`, or to what its screen
// has room for, the window manager's frame included: a dialog taller than
// a laptop's 768 pixels hid its buttons below the screen's edge.
void resizeWithinScreen(QWidget& window, int width, int height);

}  // namespace cambench
