#pragma once

namespace cambench {

// Registers every transport, family, protocol and simulator CamBench has: the one
// place a new one is added (one line). Called first by each main() and by
// the tests that open connections. Safe to call more than once.
void registerBuiltins();

}  // namespace cambench
