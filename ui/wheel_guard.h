#pragma once

class QWidget;

namespace cambench {

// A spin box or combo box under the mouse of someone scrolling a long form
// must not change its value: the wheel changes it only once the user
// clicked or tabbed into it; otherwise the wheel scrolls the page.
void guardWheel(QWidget* editor);

}  // namespace cambench
