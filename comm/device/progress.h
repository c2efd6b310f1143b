#pragma once

#include <QtGlobal>

#include <functional>

namespace cambench::comm {

// Reports how far an operation is: `done` of `total` steps.
using ProgressFn = std::function<void(qint64 done, qint64 total)>;

}  // namespace cambench::comm
