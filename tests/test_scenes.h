#pragma once
/// Helpers shared by tests: parse a scene from text or from scenes/, fail
/// loudly; compare vectors; seed property tests reproducibly.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "core/math/vec3.h"
#include "core/parse/parser.h"
#include "core/scene/scene_desc.h"

/// Each component of `actual` within `tol` of `expected`, printing both vectors.
#define EXPECT_VEC_NEAR(actual, expected, tol)                            \
    do {                                                                  \
        const ::f2::Vec3 a_ = (actual), e_ = (expected);                  \
        EXPECT_NEAR(a_.x, e_.x, (tol)) << "got " << a_ << " want " << e_; \
        EXPECT_NEAR(a_.y, e_.y, (tol)) << "got " << a_ << " want " << e_; \
        EXPECT_NEAR(a_.z, e_.z, (tol)) << "got " << a_ << " want " << e_; \
    } while (0)

namespace f2::test {

/// Every diagnostic of a parse, formatted, one per line.
std::string formatDiagnostics(const ParseResult& result);
/// Parses `text` as "t.f2": exactly one diagnostic, an error in "t.f2" at
/// line:column whose message contains `what`.
void expectOnlyError(std::string_view text, int line, int column, std::string_view what,
                     const ParseLimits& limits = ParseLimits());
/// Parses `text`; the test fails (with every diagnostic) if it has an error.
SceneDesc sceneFromText(std::string_view text);
/// Parses scenes/<name> of the source tree.
SceneDesc sceneFromRepo(const std::string& name);
/// Absolute path of a file in the source tree.
std::string sourcePath(const std::string& relative);
/// Seed of a property test: `fallback`, or F2_TEST_SEED when set; printed so a
/// failure can be replayed.
std::uint32_t testSeed(std::uint32_t fallback);

/// Built with AddressSanitizer or ThreadSanitizer (GCC's macros, clang's feature test).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
inline constexpr bool kSanitized = __has_feature(address_sanitizer) || __has_feature(thread_sanitizer);
#else
inline constexpr bool kSanitized = false;
#endif
/// How many random cases a property test draws: `n`, a fifth of it under a
/// sanitizer, which runs every case 5-20 times slower and needs only a few to
/// see each code path the release suite checks with all of them.
constexpr int randomCases(int n) { return kSanitized ? (n + 4) / 5 : n; }

}  // namespace f2::test
