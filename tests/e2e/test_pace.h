#pragma once

namespace cambench::e2e {

// How much slower than a quiet machine's normal build this run is, measured
// once per test process: the median start of `cambench-cli --version`
// against kQuietCliStartMs, and at least the build's own factor
// (CAMBENCH_TEST_TIME_SCALE, which tests/CMakeLists.txt sets: 4 for a
// sanitized build). 1.0 or more.
double testPace();

// A bound for something that takes at most `quietMs` on a quiet machine
// (a hang bound, never a performance limit), stretched by testPace().
int hangBoundMs(int quietMs);

}  // namespace cambench::e2e
