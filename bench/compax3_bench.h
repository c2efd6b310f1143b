#pragma once

namespace cambench::bench {

// Compax3 (issue 15): a 500-object parameter set read from the throttled
// simulated drive at 115200 and 9600 baud, once with one read per object
// and once through the backup use case (each object read until two answers
// agree), as time, wire bytes and the ratio to the wire limit
// (bytes x 10 / baud).
void benchCompax3();

}  // namespace cambench::bench
