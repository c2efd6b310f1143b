#pragma once

#include "comm/usecases/item_outcome.h"

namespace cambench::cli {

// A write's report on stdout, whatever the family: every item that was not
// unchanged with its outcome, then the summary ("193 items: 3 written, 190
// unchanged"). Exit 0 only when every item was written or unchanged;
// otherwise the summary goes to stderr too and the first error decides.
int printOutcomeTally(const usecases::OutcomeTally& tally);

}  // namespace cambench::cli
