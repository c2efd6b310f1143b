// Runs a fuzz function without libFuzzer: over a fixed seed corpus and
// pseudo-random inputs from a fixed seed, so every normal build exercises it.
// Each *_replay_main.cpp says only what differs: its seeds and parameters.
#pragma once

#include <QByteArray>
#include <QList>

#include <cstdint>

namespace cambench::fuzz {

// How many random inputs to make, how long, and from which seed.
struct RandomInputs {
    int count;
    int shortLengthMax;  // most inputs are at most this long ...
    int longLengthMax;   // ... one in 32 up to this, to overflow the receiver's cap
    std::uint32_t seed;
};

// Runs every seed, then random inputs through LLVMFuzzerTestOneInput: random
// bytes, bytes of `interesting` and whole short seeds spliced in, 1:2:1. An
// invariant that fails aborts; else prints "<name>: N inputs, all invariants
// held". Returns main()'s exit code.
int runReplay(const char* name, const QList<QByteArray>& seeds, const QByteArray& interesting,
              const RandomInputs& random);

}  // namespace cambench::fuzz
