#pragma once

#include "traffic_entry.h"

#include <QString>

namespace cambench::comm {

// One line of a traffic log, without line end:
// "2026-11-21T22:41:53.123 > 3F 49 46 47 57 47 34 43 0D 0A  |?IFGWG4C..|"
// local time with milliseconds, '>' sent / '<' received, the bytes in hex,
// then the printable ASCII with '.' for everything else.
QString formatTrafficEntry(const TrafficEntry& entry);

}  // namespace cambench::comm
