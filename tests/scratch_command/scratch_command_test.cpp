// A command added as docs/design.md says — one row of the language table
// (scratch_command_row.inc) and one builder function (scratch_builder.cpp) —
// reaches the parser's dispatch, argument counts and suggestions, the
// language server's completion and hover, and the generated TextMate grammar
// with nothing else written for it. Built only by tests/scratch_command's
// scratch build (the language's files compiled again with F2_SCRATCH_COMMAND).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "core/parse/language.h"
#include "core/parse/parser.h"
#include "lsp/analysis.h"
#include "lsp/features.h"
#include "lsp/language_files.h"

namespace f2 {
namespace {

std::string messages(const ParseResult& result) {
    std::string all;
    for (const Diagnostic& d : result.diagnostics) all += d.format() + "\n";
    return all;
}

lsp::Analysis analysed(std::string text) {
    return lsp::analyze("file:///scratch/a.f2", lsp::TextDocument(std::move(text), 1));
}

TEST(ScratchCommand, TheParserBuildsItFromItsRow) {
    const ParseResult result = parseScene("/scratch ball 10 1 2 3\n", "a.f2");
    ASSERT_TRUE(result.scene) << messages(result);
    ASSERT_EQ(result.scene->objects.size(), 1u);
    EXPECT_EQ(result.scene->objects[0].kind, ObjectKind::Sphere);
    EXPECT_EQ(result.scene->objects[0].name, "ball");
}

TEST(ScratchCommand, ItsArgumentCountsAreTheRows) {
    // A sphere may be turned (8 arguments); the row says 5, and only the row does.
    const ParseResult turned = parseScene("/scratch ball 10 1 2 3 0 45 0\n", "a.f2");
    EXPECT_FALSE(turned.scene);
    EXPECT_EQ(messages(turned), "a.f2:1:1: error: '/scratch' takes 5 arguments, got 8\n");
}

TEST(ScratchCommand, ItIsSuggestedForAMisspelling) {
    const ParseResult result = parseScene("/scratchy ball 10 1 2 3\n", "a.f2");
    EXPECT_EQ(messages(result), "a.f2:1:1: error: unknown command '/scratchy' (did you mean '/scratch'?)\n");
}

TEST(ScratchCommand, TheLanguageServerCompletesAndExplainsIt) {
    const lsp::Analysis a = analysed("/scr\n");
    const lsp::Json items = lsp::completion(a, {0, 4});
    bool found = false;
    for (const lsp::Json& item : items) {
        if (item.value("label", "") != "/scratch") continue;
        found = true;
        EXPECT_NE(item.dump().find("A scratch sphere of radius"), std::string::npos) << item.dump();
    }
    EXPECT_TRUE(found) << items.dump();

    const lsp::Json hover = lsp::hover(analysed("/scratch ball 10 1 2 3\n"), {0, 3});
    ASSERT_FALSE(hover.is_null());
    const std::string shown = hover.dump();
    EXPECT_NE(shown.find("/scratch <name> <r> <cx> <cy> <cz>"), std::string::npos) << shown;
    EXPECT_NE(shown.find("never turned"), std::string::npos) << shown;
}

TEST(ScratchCommand, TheGeneratedGrammarHasIt) {
    std::ifstream in(F2_GRAMMAR_TEMPLATE);
    ASSERT_TRUE(in) << F2_GRAMMAR_TEMPLATE;
    std::stringstream text;
    text << in.rdbuf();
    std::string problem;
    const std::string grammar = lsp::fillLanguageTemplate(text.str(), problem);
    ASSERT_TRUE(problem.empty()) << problem;
    // Among the creating commands, which the grammar colours as such.
    const auto creating = lsp::languageList("creating");
    ASSERT_TRUE(creating);
    EXPECT_NE(std::find(creating->begin(), creating->end(), "scratch"), creating->end());
    EXPECT_NE(grammar.find("scratch|"), std::string::npos);
    // The committed grammar, generated without the row, does not have it.
    std::ifstream committed(F2_GRAMMAR);
    std::stringstream was;
    was << committed.rdbuf();
    EXPECT_EQ(was.str().find("scratch"), std::string::npos);
}

}  // namespace
}  // namespace f2
