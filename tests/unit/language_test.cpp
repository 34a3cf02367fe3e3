// The language table (core/parse/language.h) is the one list of commands,
// options and modes: the parser and the expander run exactly its commands,
// and the generated files are filled from it (lsp/language_files.h).
#include "core/parse/language.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/parse/parser.h"

namespace f2 {
namespace {

bool saysUnknownCommand(const ParseResult& r) {
    return std::any_of(r.diagnostics.begin(), r.diagnostics.end(),
                       [](const Diagnostic& d) { return d.message.starts_with("unknown command"); });
}

TEST(LanguageTable, TheParserRunsEveryCommandOfTheTableAndNoOther) {
    for (const CommandSpec& c : commands()) {
        SCOPED_TRACE(std::string(c.name));
        // Alone on its line: wrong arguments, but a command the parser knows.
        const ParseResult r = parseScene(std::string(c.name) + "\n", "t.f2");
        EXPECT_FALSE(saysUnknownCommand(r));
    }
    EXPECT_TRUE(saysUnknownCommand(parseScene("/colour s 1 2 3\n", "t.f2")));
    EXPECT_EQ(commandNames().size(), commands().size());
}

TEST(LanguageTable, TheParserCountsArgumentsByTheRow) {
    // Hand-written, as a user reads them in the docs: the table must say so.
    EXPECT_EQ(
        std::vector<int>(command(CommandId::Camera).counts.begin(), command(CommandId::Camera).counts.end()),
        (std::vector<int>{3, 6, 9}));
    EXPECT_EQ(std::vector<int>(command(CommandId::Box).counts.begin(), command(CommandId::Box).counts.end()),
              (std::vector<int>{7, 10}));
    int counted = 0;
    for (const CommandSpec& c : commands()) {
        if (c.counts.empty()) continue;
        SCOPED_TRACE(std::string(c.name));
        ++counted;
        // One argument fewer than the fewest it takes (more could be a light's options).
        const int tooFew = c.counts.front() - 1;
        std::string line(c.name);
        for (int i = 0; i < tooFew; ++i) line += " 1";
        // `/part` stands only in a model block.
        if (c.id == CommandId::Part) line = "/model m\n" + line + "\n/end";
        const ParseResult r = parseScene(line + "\n", "t.f2");
        ASSERT_FALSE(r.diagnostics.empty());
        const std::string& message = r.diagnostics.front().message;
        EXPECT_NE(message.find("takes "), std::string::npos) << message;
        EXPECT_NE(message.find(", got " + std::to_string(tooFew)), std::string::npos) << message;
        for (int n : c.counts) EXPECT_NE(message.find(std::to_string(n)), std::string::npos) << message;
    }
    EXPECT_GE(counted, 20);
}

TEST(LanguageTable, EveryRowIsComplete) {
    for (std::size_t i = 0; i < commands().size(); ++i) {
        const CommandSpec& c = commands()[i];
        SCOPED_TRACE(std::string(c.name));
        EXPECT_EQ(static_cast<std::size_t>(c.id), i);
        EXPECT_EQ(&command(c.id), &c);
        EXPECT_EQ(findCommand(c.name), &c);
        EXPECT_TRUE(c.name.starts_with('/') && isValidName(c.name.substr(1)));
        EXPECT_TRUE(c.syntax.starts_with(c.name));
        EXPECT_TRUE(c.snippet.starts_with(c.name));
        EXPECT_FALSE(c.meaning.empty());
    }
    EXPECT_EQ(findCommand("/nope"), nullptr);
}

TEST(LanguageTable, TheCameraArgumentIsWhereTheParserTakesCamera) {
    EXPECT_EQ(command(CommandId::Key).cameraArgument(), 1);  // /key <t> camera
    EXPECT_EQ(command(CommandId::Attach).cameraArgument(), 0);
    EXPECT_EQ(command(CommandId::Paint).cameraArgument(), -1);
    EXPECT_TRUE(parseScene("/key 0 camera\n/interp camera ease\n/anim camera\n", "t.f2").ok());
    EXPECT_FALSE(parseScene("/paint camera 1 2 3\n", "t.f2").ok());
}

TEST(LanguageTable, EveryModeAndOptionParses) {
    for (Interpolation m : interpolationModes()) {
        const std::string word(interpolationName(m));
        EXPECT_EQ(modeFromWord(word), m);
        // `bezier` takes four numbers after its word, the others none.
        const std::string numbers = modeNumberCount(m) == 4 ? " 0.5 0 0.5 1" : "";
        EXPECT_EQ(modeNumberCount(m), m == Interpolation::Bezier ? 4 : 0);
        EXPECT_TRUE(parseScene("/sphere s 1 0 0 0\n/interp s " + word + numbers + "\n", "t.f2").ok()) << word;
    }
    EXPECT_FALSE(modeFromWord("smooth"));
    EXPECT_EQ(lightOptions().size(), 5u);
    for (std::size_t i = 0; i < lightOptions().size(); ++i)
        EXPECT_EQ(static_cast<std::size_t>(lightOptions()[i].option), i);
}

TEST(LanguageTable, TheNameRuleIsAsciiWhateverTheLocale) {
    EXPECT_TRUE(isValidName("_r2d2"));
    EXPECT_FALSE(isValidName("2r"));
    EXPECT_FALSE(isValidName(""));
    EXPECT_FALSE(isValidName("caf\xc3\xa9"));
    EXPECT_FALSE(isValidName("a.b"));
}

}  // namespace
}  // namespace f2
