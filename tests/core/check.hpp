// A minimal checker for the core tests: every failed check prints what was
// expected where, and the process exits non-zero when any check failed.
#pragma once

#include <cstdio>
#include <cstdlib>

namespace polymass_test {

struct Tally {
    long checks = 0;
    long failures = 0;
};

inline Tally& tally() {
    static Tally t;
    return t;
}

inline void check(bool ok, const char* what, const char* file, int line) {
    ++tally().checks;
    if (ok) return;
    ++tally().failures;
    std::fprintf(stderr, "%s:%d: FAILED: %s\n", file, line, what);
}

// Prints the summary; returns the process exit status.
inline int finish(const char* name) {
    std::printf("%s: %ld checks, %ld failed\n", name, tally().checks, tally().failures);
    return tally().failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

}  // namespace polymass_test

#define CHECK(condition) ::polymass_test::check((condition), #condition, __FILE__, __LINE__)
