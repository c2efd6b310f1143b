// Linked into every GUI test: the protocol settings widgets the GUI's
// main() registers are there for the tests too.
#include "app/gui/gui_registry.h"

namespace {

const bool kRegistered = (cambench::registerProtocolWidgets(), true);

}  // namespace
