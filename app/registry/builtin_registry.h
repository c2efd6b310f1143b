#pragma once

namespace cambench {

// Registers every transport CamBench has and every built-in family through
// its FamilyParts (builtin_registry.cpp: one line per family). Which parts
// of a family come along depends on the program this is compiled into (the
// GUI's part in the GUI, the CLI's in cambench-cli); each program then
// calls familiesComplete (family_parts.h). Called first by each main() and
// by the tests. Safe to call more than once.
void registerBuiltins();

}  // namespace cambench
