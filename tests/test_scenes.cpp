#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

#include "core/parse/parser.h"

namespace f2::test {

namespace {
SceneDesc unwrap(ParseResult result) {
    std::string all;
    for (const Diagnostic& d : result.diagnostics) all += d.format() + "\n";
    EXPECT_TRUE(result.ok()) << all;
    return result.ok() ? std::move(*result.scene) : SceneDesc{};
}
}  // namespace

SceneDesc sceneFromText(std::string_view text) { return unwrap(parseScene(text, "test.f2")); }
SceneDesc sceneFromRepo(const std::string& name) { return unwrap(parseSceneFile(sourcePath("scenes/" + name))); }
std::string sourcePath(const std::string& relative) { return std::string(F2_SOURCE_DIR) + "/" + relative; }

std::uint32_t testSeed(std::uint32_t fallback) {
    std::uint32_t seed = fallback;
    if (const char* s = std::getenv("F2_TEST_SEED")) seed = std::uint32_t(std::strtoul(s, nullptr, 10));
    std::cout << "[   SEED   ] F2_TEST_SEED=" << seed << '\n';
    return seed;
}

}  // namespace f2::test
