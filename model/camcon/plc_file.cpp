#include "plc_file.h"

namespace cambench {}  // namespace cambench
