#include "line_manifest.h"

namespace cambench {}  // namespace cambench
