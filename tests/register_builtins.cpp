// Linked into every test executable: the transports and protocols the
// programs register in main() are there for the tests too.
#include "app/registry/builtin_registry.h"

namespace {

const bool kRegistered = (cambench::registerBuiltins(), true);

}  // namespace
