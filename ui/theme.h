#pragma once

namespace cambench {

// Fusion style with an explicit light or dark palette; both are chosen so
// that text, disabled text, links and selections stay readable.
void applyTheme(bool dark);
bool isDarkTheme();

}  // namespace cambench
