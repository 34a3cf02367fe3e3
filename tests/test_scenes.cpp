#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

#include "core/parse/parser.h"

namespace f2::test {

namespace {
SceneDesc unwrap(ParseResult result) {
    EXPECT_TRUE(result.ok()) << formatDiagnostics(result);
    return result.ok() ? std::move(*result.scene) : SceneDesc{};
}
}  // namespace

std::string formatDiagnostics(const ParseResult& result) {
    std::string all;
    for (const Diagnostic& d : result.diagnostics) all += d.format() + "\n";
    return all;
}

void expectOnlyError(std::string_view text, int line, int column, std::string_view what,
                     const ParseLimits& limits) {
    SCOPED_TRACE(std::string(text));
    const ParseResult r = parseScene(text, "t.f2", limits);
    EXPECT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u) << formatDiagnostics(r);
    const Diagnostic& d = r.diagnostics[0];
    EXPECT_EQ(d.severity, Severity::Error);
    EXPECT_EQ(d.loc.file, "t.f2");
    EXPECT_EQ(d.loc.line, line) << d.format();
    EXPECT_EQ(d.loc.column, column) << d.format();
    EXPECT_NE(d.message.find(what), std::string::npos) << "message: " << d.message << "\nexpected: " << what;
}

SceneDesc sceneFromText(std::string_view text) { return unwrap(parseScene(text, "test.f2")); }
SceneDesc sceneFromRepo(const std::string& name) {
    return unwrap(parseSceneFile(sourcePath("scenes/" + name)));
}
std::string sourcePath(const std::string& relative) { return std::string(F2_SOURCE_DIR) + "/" + relative; }

std::uint32_t testSeed(std::uint32_t fallback) {
    std::uint32_t seed = fallback;
    if (const char* s = std::getenv("F2_TEST_SEED")) seed = std::uint32_t(std::strtoul(s, nullptr, 10));
    std::cout << "[   SEED   ] F2_TEST_SEED=" << seed << '\n';
    return seed;
}

}  // namespace f2::test
