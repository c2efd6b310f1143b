#pragma once

#include <QImage>

namespace cambench {

class CamDocument;

// A cam program's diagram drawn for paper: outputs `first`..`last` (one row
// each, with number and name), the axis IMIN..IMAX with its ticks, every
// cam as a bar (two for one that wraps through zero), tracks that differ
// from the device hatched. Black on white whatever the screen's palette;
// no selection, cursor, live position or scroll bars.
QImage printDiagram(const CamDocument& cams, int program, int first, int last, int width);

}  // namespace cambench
