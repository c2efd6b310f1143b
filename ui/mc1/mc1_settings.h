#pragma once

#include "model/mc1/mc1_project_file.h"

#include <optional>

namespace cambench::mc1settings {

// The MC-1 watch list of the last session - the variables watched and the
// names given to them, no values (what a controller held yesterday is no
// value to show) - kept in the GUI's settings like the connection is, and
// restored without a question when CamBench starts.
void saveWatchList(const Mc1Project& project);
// Nothing when none was kept or what was kept is not a watch list.
std::optional<Mc1Project> loadWatchList();

}  // namespace cambench::mc1settings
