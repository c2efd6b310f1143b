// Linked into every test executable: the transports and families the
// programs register in main() are there for the tests too (with the
// families' GUI parts in a test that links cambench_gui_registry).
#include "app/registry/builtin_registry.h"

namespace {

const bool kRegistered = (cambench::registerBuiltins(), true);

}  // namespace
