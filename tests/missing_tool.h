#pragma once
/// A GoogleTest case that needs a program the machine lacks: skipped with the
/// reason, or failed when F2_REQUIRE_ALL_TESTS=1 (.ci/run sets it, since there
/// every package can be installed; tests/skip.sh is the shell tests' twin).
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

namespace f2::test {

inline bool requireAllTests() {
    const char* v = std::getenv("F2_REQUIRE_ALL_TESTS");
    return v != nullptr && std::strcmp(v, "1") == 0;
}

}  // namespace f2::test

/// Ends the test: FAIL() under F2_REQUIRE_ALL_TESTS=1, else GTEST_SKIP(); `reason` streams.
#define F2_SKIP_MISSING(reason)                                                                     \
    do {                                                                                            \
        if (::f2::test::requireAllTests()) {                                                        \
            FAIL() << reason << " (F2_REQUIRE_ALL_TESTS=1: nothing the tests need may be missing)"; \
        }                                                                                           \
        GTEST_SKIP() << reason;                                                                     \
    } while (false)
