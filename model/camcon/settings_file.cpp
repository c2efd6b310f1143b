#include "settings_file.h"

namespace cambench {}  // namespace cambench
