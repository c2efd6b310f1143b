// The invariant check shared by the fuzz functions.
#pragma once

#include <cstdio>
#include <cstdlib>

// Fails loudly in every build type (assert() is gone in release builds).
#define FUZZ_CHECK(condition)                                                           \
    do {                                                                                \
        if (!(condition)) {                                                             \
            std::fprintf(stderr, "%s:%d: invariant violated: %s\n", __FILE__, __LINE__, \
                         #condition);                                                   \
            std::abort();                                                               \
        }                                                                               \
    } while (false)
