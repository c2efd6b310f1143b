// Linked into every GUI test (which links cambench_gui_registry, so that
// register_builtins.cpp registers the families with their GUI parts): the
// GUI program's startup check, so that a GUI test stops at start as the
// program would when a family lacks a part.
#include "app/registry/builtin_registry.h"
#include "app/registry/family_parts.h"

#include <cstdlib>

namespace {

const bool kChecked = [] {
    cambench::registerBuiltins();  // the order of static initialisers is not known
    if (!cambench::familiesComplete(cambench::Program::Gui, "GUI test")) std::exit(70);
    return true;
}();

}  // namespace
