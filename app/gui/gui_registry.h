#pragma once

namespace cambench {

// Registers what the GUI has of every protocol and family: each protocol's
// settings widget (ui/protocols) and each family's pages, menus and reads
// (FamilyGuiRegistry), one line each; the one place a new protocol or
// family is added to the GUI. Called by the GUI's main() and the GUI tests.
// Safe to call more than once.
void registerGuiParts();

}  // namespace cambench
