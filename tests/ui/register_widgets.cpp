// Linked into every GUI test: the protocol settings widgets and family GUI
// parts the GUI's main() registers are there for the tests too.
#include "app/gui/gui_registry.h"

namespace {

const bool kRegistered = (cambench::registerGuiParts(), true);

}  // namespace
