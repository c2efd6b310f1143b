#pragma once

namespace cambench {

// Registers the settings widget of every protocol (ui/protocols): the one
// place a new protocol's widget is added (one line). Called by the GUI's
// main() and the GUI tests. Safe to call more than once.
void registerProtocolWidgets();

}  // namespace cambench
