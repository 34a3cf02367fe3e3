// Second edition of the scene language, SPEC 9.4 and 9.5: /let, ( … ) and
// { … }, /repeat … /end, /include, their limits, and every error with its
// exact FILE:LINE:COL and loop values.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/parse/parser.h"
#include "test_scenes.h"

namespace f2 {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFile = "t.f2";

std::string dump(const ParseResult& r) { return test::formatDiagnostics(r); }

SceneDesc parseOk(std::string_view text, const ParseLimits& limits = ParseLimits()) {
    ParseResult r = parseScene(text, kFile, limits);
    EXPECT_FALSE(hasErrors(r.diagnostics)) << dump(r);  // whole-scene warnings (no light...) are fine
    return r.scene.value_or(SceneDesc{});
}

/// Exactly one diagnostic, an error at line:column whose message contains `what`.
void expectError(std::string_view text, int line, int column, std::string_view what,
                 const ParseLimits& limits = ParseLimits()) {
    test::expectOnlyError(text, line, column, what, limits);
}

/// The diagnostics, each starting and ending as given (the middle, such as
/// "first defined at", is other tests' business).
template <typename Pairs>
void expectDiagnostics(const ParseResult& r, const Pairs& expected) {
    ASSERT_EQ(r.diagnostics.size(), std::size(expected)) << dump(r);
    for (std::size_t k = 0; k < std::size(expected); ++k) {
        const std::string line = r.diagnostics[k].format();
        EXPECT_TRUE(line.starts_with(expected[k].first)) << line;
        EXPECT_TRUE(line.ends_with(expected[k].second)) << line;
    }
}

std::vector<std::string> names(const SceneDesc& s) {
    std::vector<std::string> n;
    for (const SceneObject& o : s.objects) n.push_back(o.name);
    return n;
}

float radius(const SceneDesc& s, std::string_view name) {
    for (const SceneObject& o : s.objects) {
        if (o.name == name) return o.size.x;
    }
    ADD_FAILURE() << "no object " << name;
    return -1;
}

// /let and expressions (SPEC 9.4)

TEST(Let, DefinesAndRedefinesVariables) {
    const SceneDesc s = parseOk(
        "/let r 50\n"
        "/sphere a (r) 0 0 0\n"
        "/let r (r * 2 + 1)\n"
        "/sphere b (r) ( 1 + 2 ) (-r) (2^3)\n");
    EXPECT_EQ(radius(s, "a"), 50);
    EXPECT_EQ(radius(s, "b"), 101);
    EXPECT_EQ(s.objects[1].rest.position, (Vec3{3, -101, 8}));
}

TEST(Let, PiIsPredefined) {
    const SceneDesc s = parseOk("/sphere a (pi) 0 0 0\n/sphere b (2 * pi) 0 0 0\n");
    EXPECT_FLOAT_EQ(radius(s, "a"), 3.14159265f);
    expectError("/let pi 3\n", 1, 6, "'pi' is predefined and cannot be redefined");
}

TEST(Let, Errors) {
    expectError("/let x\n", 1, 1, "'/let' takes 2 arguments (a variable and a number), got 1");
    expectError("/let x 1 2\n", 1, 1, "'/let' takes 2 arguments");
    expectError("/let 1x 3\n", 1, 6, "invalid variable name '1x'");
    expectError("/let x abc\n", 1, 8, "expected a number, got 'abc'");
    expectError("/let x (y)\n", 1, 9, "unknown variable 'y'");
    // A variable alone is not a number: write (x).
    expectError("/let x 5\n/sphere s x 0 0 0\n", 2, 11, "expected a number, got 'x'");
    // Variables and object names are separate.
    parseOk("/sphere s 1 0 0 0\n/let s 2\n/sphere t (s) 0 0 0\n");
}

TEST(Expressions, ErrorsPointIntoTheExpression) {
    expectError("/sphere s (1/0) 0 0 0\n", 1, 13, "division by zero");
    expectError("/sphere s 1 ( 2 + q ) 0 0\n", 1, 19, "unknown variable 'q'");
    expectError("/sphere s (sqrt(-1)) 0 0 0\n", 1, 12, "sqrt(-1) is undefined");
    expectError("/sphere s (log(0)) 0 0 0\n", 1, 12, "log(0) is undefined");
    expectError("/sphere s (asin(2)) 0 0 0\n", 1, 12, "asin(2) is undefined");
    expectError("/sphere s (tan(90)) 0 0 0\n", 1, 12, "tan(90) is undefined");
    expectError("/sphere s (foo(1)) 0 0 0\n", 1, 12, "unknown function 'foo'");
    expectError("/sphere s (10^400) 0 0 0\n", 1, 14, "not finite");
    expectError("/fps (1 + 2\n", 1, 6, "this '(' has no matching ')'");
    expectError("/sphere s (1)(2) 0 0 0\n", 1, 14, "after the ')'");
    // Beyond single precision, as for a number.
    expectError("/sphere s (1e30 * 1e10) 0 0 0\n", 1, 11, "is out of range");
    // The checks of the field apply to the value.
    expectError("/sphere s (1 - 2) 0 0 0\n", 1, 11, "radius must be > 0, got -1");
}

TEST(Expressions, AnUnknownCommandIsOneErrorNotOnePerArgument) {
    // Its arguments are not evaluated: nothing would use their values.
    expectError("/sphre s (1/0) 0 0 0\n", 1, 1, "unknown command '/sphre' (did you mean '/sphere'?)");
    expectError("/frob a{z} (y)\n", 1, 1, "unknown command '/frob'");
    expectError("State: R (running)\n", 1, 1, "expected a command starting with '/', got 'State:'");
}

TEST(Expressions, IntegerFieldsTakeValuesWithinOneMillionth) {
    EXPECT_EQ(parseOk("/fps (24.0000004)\n").fps, 24);
    EXPECT_EQ(parseOk("/fps (100 / 3 * 3)\n").fps, 100);
    EXPECT_EQ(parseOk("/background (255) (0.1*3*10) 0\n").background, (Color8{255, 3, 0}));
    expectError("/fps (24.1)\n", 1, 6, "fps must be a whole number from 1 to 1000, got 24.1");
    // A number as written must still be exactly whole (SPEC 7).
    expectError("/fps 24.0000004\n", 1, 6, "fps must be a whole number");
}

TEST(Expressions, DeepParenthesesAreAClearError) {
    const std::string deep = "/fps " + std::string(5000, '(') + "1" + std::string(5000, ')') + "\n";
    expectError(deep, 1, 6 + 256, "nested more than 256 levels");
}

TEST(NameInterpolation, BracesGiveWholeNumbers) {
    const SceneDesc s = parseOk(
        "/let i 2\n"
        "/sphere r{i+1} 1 0 0 0\n"
        "/sphere r{ i * 10 }_{i} 1 0 0 0\n"
        "/sphere big{1e3} 1 0 0 0\n"
        "/paint r3 1 2 3\n"
        "/key 4 r{i+1}\n");
    EXPECT_EQ(names(s), (std::vector<std::string>{"r3", "r20_2", "big1000"}));
    EXPECT_EQ(s.objects[0].appearance[0].color, (Color8{1, 2, 3}));
    ASSERT_EQ(s.objects[0].track.keys.size(), 1u);
    EXPECT_EQ(s.objects[0].track.keys[0].time, 4);
}

TEST(NameInterpolation, Errors) {
    expectError("/sphere r{0.5} 1 0 0 0\n", 1, 10, "'{...}' in a name must give a whole number, got 0.5");
    expectError("/sphere r{k} 1 0 0 0\n", 1, 11, "unknown variable 'k'");
    expectError("/anim r{1\n", 1, 8, "this '{' has no matching '}'");
    expectError("/robot a 0 0 0\n/let i 1\n/key 0 a.leg{i}\n", 3, 10, "unknown part 'leg1'");
}

// Conditions in expressions (SPEC 10.7)

TEST(Conditions, ChooseAValueInAScene) {
    const SceneDesc s = parseOk(
        "/let k 2\n"
        "/sphere s 1 (if(k == 2, 10, 20)) 0 0\n"
        "/sphere t 1 (if(k != 2, 10, 20)) (k > 1 && k < 3) (!k)\n");
    EXPECT_EQ(s.objects[0].rest.position, (Vec3{10, 0, 0}));
    EXPECT_EQ(s.objects[1].rest.position, (Vec3{20, 1, 0}));
    // Only the branch returned is evaluated: no division by zero here.
    EXPECT_EQ(radius(parseOk("/sphere s (if(0, 1/0, 5)) 0 0 0\n"), "s"), 5);
    EXPECT_EQ(radius(parseOk("/let n 0\n/sphere s (n == 0 || 1/n > 2) 0 0 0\n"), "s"), 1);
}

TEST(Conditions, OnePassOfALoopGetsAnotherColour) {
    // What the trial wrote as 60 * (1 - min(k, 1)).
    const SceneDesc s = parseOk(
        "/repeat i 0 3\n"
        "  /sphere b{i} 5 (i * 20) 0 0\n"
        "  /paint b{i} (if(i == 0, 255, 80)) 80 80\n"
        "/end\n");
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.objects[0].appearance[0].color, (Color8{255, 80, 80}));
    for (std::size_t k = 1; k < 4; ++k)
        EXPECT_EQ(s.objects[k].appearance[0].color, (Color8{80, 80, 80})) << k;
}

TEST(Conditions, InNames) {
    const SceneDesc s = parseOk(
        "/repeat i 1 3\n"
        "  /sphere s{i}_{i == 2} 1 0 0 0\n"
        "/end\n");
    EXPECT_EQ(names(s), (std::vector<std::string>{"s1_0", "s2_1", "s3_0"}));
}

TEST(Conditions, ErrorsPointIntoTheExpression) {
    expectError("/let k 2\n/sphere s 1 (k = 2) 0 0\n", 2, 16,
                "'=' is not an operator: to compare, write '=='; to set a variable, use /let");
    expectError("/sphere s 1 (if(1, 2)) 0 0\n", 1, 14,
                "'if' takes 3 arguments, got 2 (write if(condition, value if true, value if false))");
    expectError("/sphere s 1 (1 && 1/0) 0 0\n", 1, 20, "division by zero");
    expectError("/sphere s 1 (if(0, q, 1)) 0 0\n", 1, 20, "unknown variable 'q'");
    expectError("/sphere s{1 & 1} 1 0 0 0\n", 1, 13, "'&' is not an operator: for 'and', write '&&'");
    expectError("/repeat i 0 1\n/sphere s{i} 1 (0 < i < 1) 0 0\n/end\n", 2, 23,
                "comparisons do not chain: to test both, write 'a < b && b < c'; otherwise put the first in "
                "parentheses (in /repeat i = 0) (and in 1 more pass)");
}

// /repeat … /end (SPEC 9.5)

TEST(Repeat, RunsTheBodyForEachValue) {
    const SceneDesc s = parseOk(
        "/repeat i 1 3\n"
        "  /sphere s{i} (i) 0 0 0\n"
        "/end\n");
    EXPECT_EQ(names(s), (std::vector<std::string>{"s1", "s2", "s3"}));
    EXPECT_EQ(radius(s, "s3"), 3);
}

TEST(Repeat, StepsUpDownAndFractional) {
    EXPECT_EQ(names(parseOk("/repeat i 3 1 -1\n/sphere s{i} 1 0 0 0\n/end\n")),
              (std::vector<std::string>{"s3", "s2", "s1"}));
    EXPECT_EQ(names(parseOk("/repeat x 0 1 0.25\n/sphere s{x*4} 1 0 0 0\n/end\n")),
              (std::vector<std::string>{"s0", "s1", "s2", "s3", "s4"}));
    // 0.1 steps: x = 0 + k * 0.1, and 10 * 0.1 is 1 exactly, so 1 is the eleventh pass.
    EXPECT_EQ(parseOk("/repeat x 0 1 0.1\n/sphere s{round(x*10)} 1 0 0 0\n/end\n").objects.size(), 11u);
    EXPECT_EQ(names(parseOk("/repeat i 0 10 5\n/sphere s{i} 1 0 0 0\n/end\n")),
              (std::vector<std::string>{"s0", "s5", "s10"}));
    EXPECT_EQ(names(parseOk("/repeat i 0 9 5\n/sphere s{i} 1 0 0 0\n/end\n")),
              (std::vector<std::string>{"s0", "s5"}));
}

TEST(Repeat, AZeroPassLoopSkipsItsBody) {
    // The body is not read at all: its errors are not reported.
    const SceneDesc s = parseOk("/repeat i 1 0\n/nonsense\n/end\n/sphere a 1 0 0 0\n");
    EXPECT_EQ(names(s), (std::vector<std::string>{"a"}));
}

TEST(Repeat, NestsAndRestoresTheLoopVariable) {
    const SceneDesc s = parseOk(
        "/let i 7\n"
        "/repeat i 0 1\n"
        "  /repeat j 0 2\n"
        "    /sphere s{i}_{j} 1 (j) 0 0\n"
        "  /end\n"
        "/end\n"
        "/sphere after (i) 0 0 0\n");
    EXPECT_EQ(names(s), (std::vector<std::string>{"s0_0", "s0_1", "s0_2", "s1_0", "s1_1", "s1_2", "after"}));
    EXPECT_EQ(radius(s, "after"), 7);
    // A loop variable that did not exist before is undefined again after /end.
    expectError("/repeat j 0 1\n/end\n/sphere z (j) 0 0 0\n", 3, 12, "unknown variable 'j'");
}

TEST(Repeat, ErrorsInsideNameTheLineAndTheLoopValues) {
    ParseResult r = parseScene(
        "/repeat i 1 2\n"
        "  /repeat j 0 1 0.5\n"
        "    /sphere s{i} 1 0 0 0\n"
        "  /end\n"
        "/end\n",
        kFile);
    EXPECT_FALSE(r.ok());
    // The same error at the same place in later passes is counted, not repeated
    // (issue 29); the first definition names its own pass, not only its place.
    const std::pair<const char*, const char*> expected[] = {
        {"t.f2:3:13: error: duplicate name 's1' (first defined at 3:13 in /repeat i = 1, j = 0)",
         "(in /repeat i = 1, j = 0.5) (and in 1 more pass)"},
        {"t.f2:3:13: error: duplicate name 's2' (first defined at 3:13 in /repeat i = 2, j = 0)",
         "(in /repeat i = 2, j = 0.5) (and in 1 more pass)"},
    };
    expectDiagnostics(r, expected);
}

TEST(Repeat, Errors) {
    expectError("/repeat i 0 3 0\n/end\n", 1, 15, "the step of '/repeat' must not be 0");
    expectError("/repeat i 0\n/end\n", 1, 1, "'/repeat' takes 3 or 4 arguments");
    expectError("/repeat pi 0 1\n/end\n", 1, 9, "'pi' is predefined and cannot be a loop variable");
    expectError("/repeat 2x 0 1\n/end\n", 1, 9, "invalid variable name '2x'");
    expectError("/repeat i 0 x\n/end\n", 1, 13, "expected a number, got 'x'");
    expectError("/sphere a 1 0 0 0\n/end\n", 2, 1, "'/end' without '/repeat'");
    expectError("/sphere a 1 0 0 0\n  /repeat i 0 1\n/sphere b 1 0 0 0\n", 2, 3,
                "'/repeat' without '/end' in the same file");
    // The /end of an inner loop is paired first: the outer one is left open.
    expectError("/repeat i 0 1\n/repeat j 0 1\n/end\n", 1, 1, "'/repeat' without '/end'");
    // A bad /repeat skips its body, so it is reported once, not per pass.
    expectError("/repeat i 0 1e12 0\n/sphere s 1 0 0 0\n/sphere s 1 0 0 0\n/end\n", 1, 18, "must not be 0");
}

// Issue 29: one bad `/let` gave 1 real error and 99 `unknown variable` follow-ons.
TEST(Let, AFailedLetIsOneErrorNotOnePerUse) {
    for (const char* let : {"/let r = 5 +\n", "/let r 5x\n", "/let r (1/0)\n", "/let r (q)\n"}) {
        SCOPED_TRACE(let);
        const ParseResult r = parseScene(
            std::string(let) + "/repeat k 0 99\n  /sphere s{k} (r) 0 0 {k}\n  /sphere t{r} 1 0 0 0\n/end\n",
            kFile);
        ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r);
        EXPECT_FALSE(r.ok());
    }
}

TEST(Let, AFailedLetDoesNotHideOtherUnknownNames) {
    const ParseResult r =
        parseScene("/let r 5x\n/sphere s (r + q) 0 0 0\n/let r 2\n/sphere t (r + q) 0 0 0\n", kFile);
    const std::pair<const char*, const char*> expected[] = {
        {"t.f2:1:8: error:", "got '5x'"},
        {"t.f2:4:16: error: unknown variable 'q'", "'q'"},  // r is defined again: its use is fine
    };
    expectDiagnostics(r, expected);
}

TEST(Repeat, RepeatedErrorsStillStopAtTheErrorLimit) {
    ParseLimits limits;
    limits.maxErrors = 10;
    const ParseResult r = parseScene("/repeat k 0 999999\n  /sphere s{k} -1 0 0 0\n/end\n", kFile, limits);
    ASSERT_EQ(r.diagnostics.size(), 2u) << dump(r);
    EXPECT_TRUE(r.diagnostics[0].message.ends_with("(in /repeat k = 0) (and in 9 more passes)")) << dump(r);
    EXPECT_EQ(r.diagnostics[1].message, "too many errors (10); parsing stopped here");
}

// Issue 29: "duplicate name 'tower1' (first defined at 3:9)" pointed at itself.
TEST(Repeat, ADuplicateNamesThePassOfTheFirstDefinition) {
    const ParseResult r = parseScene(
        "/sphere base 1 0 0 0\n/repeat k 0 3\n/sphere tower1 10 0 0 {k}\n/sphere base 1 0 0 0\n/end\n",
        kFile);
    const std::pair<const char*, const char*> expected[] = {
        {"t.f2:4:9: error: duplicate name 'base' (first defined at 1:9)",
         "(in /repeat k = 0) (and in 3 more passes)"},
        {"t.f2:3:9: error: duplicate name 'tower1' (first defined at 3:9 in /repeat k = 0)",
         "(in /repeat k = 1) (and in 2 more passes)"},
    };
    expectDiagnostics(r, expected);
}

TEST(Repeat, EndTakesNoArguments) {
    ParseResult r = parseScene("/repeat i 1 2\n/end i\n", kFile);
    ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r);
    EXPECT_EQ(r.diagnostics[0].format(),
              "t.f2:2:6: error: '/end' takes no arguments (in /repeat i = 1) (and in 1 more pass)");
}

/// `text` gives exactly the one diagnostic `message`, before its loops ran.
void expectRefusedAtOnce(std::string_view text, std::string_view message) {
    const ParseResult r = parseScene(text, kFile);
    ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r);
    EXPECT_EQ(r.diagnostics[0].format(), message);
    EXPECT_LT(r.linesRead, 10u);
}

TEST(Repeat, AHugeLoopFailsBeforeItRuns) {
    // 1e12 passes of one line each: refused at once, nothing is run.
    expectRefusedAtOnce("/repeat i 0 1e12\n/sphere s{i} 1 0 0 0\n/end\n",
                        "t.f2:1:1: error: this loop would read at least 2000000000002 lines (1000000000001 "
                        "passes) after 1, more than the limit of 10000000 lines read in all");
    // An empty body still costs its /end per pass.
    expectError("/repeat i 0 1e12\n/end\n", 1, 1, "this loop would read at least 1000000000001 lines");
    // Nested, the inner loop's bounds numbers: the outer loop counts its
    // passes too (1 + (10^9 + 1) * 1 + 1 lines a pass), and is refused at once.
    expectError("/repeat i 1 1\n  /repeat j 0 1e9\n  /end\n/end\n", 1, 1,
                "this loop would read at least 1000000003 lines (1 passes)");
    // An inner loop with an expression for a bound is refused when it starts.
    expectError("/repeat i 1 1\n  /repeat j 0 (1e9)\n  /end\n/end\n", 2, 3,
                "this loop would read at least 1000000001 lines");
    // Found on a later pass of the outer loop: reading stops there, with one error.
    expectError(
        "/repeat i 1 3\n  /repeat j 1 (i + 2)\n  /end\n/end\n", 2, 3,
        "this loop would read at least 4 lines (4 passes) after 7, more than the limit of 10 lines read in "
        "all (in /repeat i = 2)",
        [] {
            ParseLimits l;
            l.maxExpandedLines = 10;
            return l;
        }());
}

TEST(Repeat, InnerLoopsWithNumbersForBoundsAreForeseen) {
    // 5,000 x 5,000 passes of a comment: refused before the first line is read,
    // not after ten million of them.
    expectRefusedAtOnce(
        "/repeat a 1 5000\n/repeat b 1 5000\n#\n/end\n/end\n",
        "t.f2:1:1: error: this loop would read at least 50010000 lines (5000 passes) after 1, "
        "more than the limit of 10000000 lines read in all");
    // Three deep: each level multiplies.
    expectError("/repeat a 1 300\n/repeat b 1 300\n/repeat c 1 300\n/end\n/end\n/end\n", 1, 1,
                "at least 27180600 lines (300 passes)");
    // Exactly at the limit still runs: 1 + 2 * (1 + 3 * (1 + 1) + 1) = 17 lines.
    ParseLimits limits;
    limits.maxExpandedLines = 17;
    parseOk("/repeat a 1 2\n/repeat b 1 3\n#\n/end\n/end\n", limits);
    limits.maxExpandedLines = 16;
    expectError("/repeat a 1 2\n/repeat b 1 3\n#\n/end\n/end\n", 1, 1, "at least 16 lines (2 passes) after 1",
                limits);
    // An inner loop that will be refused reads nothing: it is not counted.
    ParseLimits shallow;
    shallow.maxLoopDepth = 1;
    expectError("/repeat a 1 1\n/repeat b 1 1e12\n/end\n/end\n", 2, 1, "loops are nested more than 1 deep",
                shallow);
    expectError("/repeat a 1 1\n/repeat pi 1 1e12\n/end\n/end\n", 2, 9, "'pi' is predefined");
}

TEST(Repeat, AStepTooSmallToMoveTheValueIsCountedAtOnce) {
    // 1e16 + k * 1e-10 stays 1e16 for about 10^10 passes: counted, not walked.
    expectError("/repeat i 1e16 1e16 1e-10\n/end\n", 1, 1,
                "this loop would read at least 10000000001 lines (10000000001 passes)");
    // Here it never moves: the count stops at 2^53, far beyond any limit.
    expectError("/repeat i -1e30 -1e30 -1e-5\n/end\n", 1, 1,
                "this loop would read at least 9007199254740992");
    // Rounding near the end of an ordinary loop still gives the exact count.
    EXPECT_EQ(parseOk("/repeat x 1 0 -0.1\n/sphere s{round(x*10)} 1 0 0 0\n/end\n").objects.size(), 11u);
    EXPECT_EQ(parseOk("/repeat x 0 0.3 0.1\n/sphere s{round(x*10)} 1 0 0 0\n/end\n").objects.size(), 3u);
}

TEST(Repeat, TheLineLimitCountsEveryPass) {
    ParseLimits limits;
    limits.maxExpandedLines = 20;
    // 3 + 6 * 3 = 21 lines read: one too many, found when the loop starts.
    expectError("#\n#\n/repeat i 1 6\n#\n#\n/end\n", 3, 1, "more than the limit of 20 lines read in all",
                limits);
    parseOk("#\n/repeat i 1 6\n#\n#\n/end\n", limits);  // 1 + 1 + 6 * 3 = 20
    // Loops hidden in includes cannot be foreseen; the count stops them as it goes.
    ParseResult r = parseScene(std::string(25, '\n'), kFile, limits);
    ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r);
    EXPECT_EQ(
        r.diagnostics[0].format(),
        "t.f2:21:1: error: more than 20 lines read in all (each pass of a loop and each include counts)");
}

TEST(Repeat, TheByteLimitCountsEveryPassToo) {
    ParseLimits limits;
    limits.maxExpandedBytes = 100;
    // Each pass reads "# 20 bytes of text.\n" (20) and "/end\n" (5).
    expectError(
        "/repeat i 1 4\n# 20 bytes of text.\n/end\n", 1, 1,
        "this loop would read at least 100 bytes (4 passes) after 14, more than the limit of 100 bytes",
        limits);
    parseOk("/repeat i 1 3\n# 20 bytes of text.\n/end\n", limits);
    ParseResult r = parseScene(std::string(60, '#') + "\n" + std::string(60, '#') + "\n", kFile, limits);
    ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r);
    EXPECT_EQ(
        r.diagnostics[0].format(),
        "t.f2:2:1: error: more than 100 bytes read in all (each pass of a loop and each include counts)");
}

TEST(Let, AFailedExpressionLeavesTheVariableAlone) {
    ParseResult r = parseScene("/let x 2\n/let x (1/0)\n/sphere s (x) 0 0 0\n", kFile);
    ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r);
    EXPECT_EQ(r.diagnostics[0].format(), "t.f2:2:10: error: division by zero");
}

TEST(Repeat, LoopsNestAtMost64Deep) {
    std::string ok, tooDeep;
    for (int i = 0; i < 64; ++i) ok += "/repeat v" + std::to_string(i) + " 1 1\n";
    for (int i = 0; i < 64; ++i) ok += "/end\n";
    parseOk(ok);
    for (int i = 0; i < 65; ++i) tooDeep += "/repeat v" + std::to_string(i) + " 1 1\n";
    for (int i = 0; i < 65; ++i) tooDeep += "/end\n";
    expectError(tooDeep, 65, 1, "loops are nested more than 64 deep");
}

TEST(Repeat, CountsLinesRead) {
    const ParseResult r = parseScene("/repeat i 1 4\n/sphere s{i} 1 0 0 0\n/end\n", kFile);
    EXPECT_TRUE(r.ok()) << dump(r);
    EXPECT_EQ(r.linesInFiles, 3u);
    EXPECT_EQ(r.linesRead, 1u + 4u * 2u);
}

// /include (SPEC 9.5)

class Include : public ::testing::Test {
   protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("f2_include_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& relative, const std::string& text) {
        const fs::path p = dir_ / relative;
        fs::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    std::string path(const std::string& relative) const { return (dir_ / relative).string(); }

    fs::path dir_;
};

TEST_F(Include, ReadsFilesRelativeToTheIncludingFile) {
    write("parts/robots.f2", "/include ../common/size.f2\n/robot r{n} 0 0 0\n");
    write("common/size.f2", "/let n 4\n");
    const std::string main = write("main.f2", "/include parts/robots.f2\n/sphere s (n) 0 0 0\n");
    const ParseResult r = parseSceneFile(main);
    ASSERT_TRUE(r.ok()) << dump(r);
    EXPECT_EQ(names(*r.scene), (std::vector<std::string>{"r4", "s"}));
    EXPECT_EQ(radius(*r.scene, "s"), 4);  // variables are shared
    EXPECT_EQ(r.files, (std::vector<std::string>{main, path("parts/robots.f2"), path("common/size.f2")}));
    EXPECT_EQ(r.linesRead, 5u);
}

// Issue 29: an include that uses an undefined `{id}` in a 33-pass loop printed
// 102 lines, each use twice (`unknown variable`, then `invalid target`).
TEST_F(Include, OneMistakeInALoopIsReportedOncePerPlace) {
    write("cap.f2",
          "/sphere cap{id} 10 0 0 0\n/material cap{id} 0.2 0.5 0.3 10\n/anim cap{id}\n/attach cap{id} r\n");
    const std::string main = write("main.f2", "/robot r 0 0 0\n/repeat k 0 32\n/include cap.f2\n/end\n");
    const ParseResult r = parseSceneFile(main);
    const std::string cap = path("cap.f2");
    const std::pair<std::string, std::string> expected[] = {
        {cap + ":1:13: error: unknown variable 'id'", "(in /repeat k = 0) (and in 32 more passes)"},
        {cap + ":2:15: error: unknown variable 'id'", "(in /repeat k = 0) (and in 32 more passes)"},
        {cap + ":3:11: error: unknown variable 'id'", "(in /repeat k = 0) (and in 32 more passes)"},
        {cap + ":4:13: error: unknown variable 'id'", "(in /repeat k = 0) (and in 32 more passes)"},
    };
    expectDiagnostics(r, expected);
}

TEST_F(Include, TheSameErrorFromAFileIncludedTwiceIsCounted) {
    write("bad.f2", "/material ghost 0.2 0.5 0.3 10\n");
    const std::string main = write("main.f2", "/include bad.f2\n/include bad.f2\n/include bad.f2\n");
    const ParseResult r = parseSceneFile(main);
    ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r);
    EXPECT_EQ(r.diagnostics[0].format(),
              path("bad.f2") + ":1:11: error: unknown name 'ghost' (and 2 more times)");
}

TEST_F(Include, QuotedPathsMayHoldSpaces) {
    write("my parts/a #1.f2", "/sphere a 1 0 0 0\n");
    const std::string main = write("main.f2", "/include \"my parts/a #1.f2\"  # a comment\n");
    const ParseResult r = parseSceneFile(main);
    ASSERT_TRUE(r.ok()) << dump(r);
    EXPECT_EQ(names(*r.scene), (std::vector<std::string>{"a"}));
}

TEST_F(Include, ErrorsNameTheIncludedFile) {
    write("sub/bad.f2", "\n/sphere b 1 0 0 zz\n");
    const std::string main = write("main.f2", "/repeat i 1 2\n/include sub/bad.f2\n/end\n/fps 0\n");
    const ParseResult r = parseSceneFile(main);
    const std::string bad = path("sub/bad.f2");
    const std::pair<std::string, std::string> expected[] = {
        {bad + ":2:17: error: expected a number, got 'zz'", "(in /repeat i = 1) (and in 1 more pass)"},
        {bad + ":2:9: error: duplicate name 'b' (first defined at 2:9 in /repeat i = 1)",
         "(in /repeat i = 2)"},
        {main + ":4:6: error: fps must be a whole number from 1 to 1000, got 0", "got 0"},
    };
    expectDiagnostics(r, expected);
}

TEST_F(Include, FileProblemsAreErrorsAtThePath) {
    const std::string main = write("main.f2",
                                   "/include nope.f2\n"
                                   "/include sub\n"
                                   "/include fifo.f2\n"
                                   "/include\n"
                                   "/include a b\n"
                                   "/include \"open\n");
    fs::create_directories(dir_ / "sub");
    ASSERT_EQ(::mkfifo(path("fifo.f2").c_str(), 0600), 0);
    const ParseResult r = parseSceneFile(main);  // must not block on the FIFO
    std::vector<std::string> lines;
    for (const Diagnostic& d : r.diagnostics) lines.push_back(d.format());
    EXPECT_EQ(
        lines,
        (std::vector<std::string>{
            main + ":1:10: error: cannot include '" + path("nope.f2") + "': No such file or directory",
            main + ":2:10: error: cannot include '" + path("sub") + "': it is a directory",
            main + ":3:10: error: cannot include '" + path("fifo.f2") + "': it is not a regular file",
            main +
                ":4:1: error: '/include' takes 1 argument (a path, in double quotes if it has spaces), got 0",
            main +
                ":5:1: error: '/include' takes 1 argument (a path, in double quotes if it has spaces), got 2",
            main + ":6:10: error: this '\"' has no closing '\"'",
        }));
    // The viewer watches the files that were tried too, so creating one reloads.
    EXPECT_EQ(r.files, (std::vector<std::string>{main, path("nope.f2"), path("sub"), path("fifo.f2")}));
}

TEST_F(Include, PathForms) {
    write("part7.f2", "/sphere seven 1 0 0 0\n");
    const std::string main = write("main.f2",
                                   "/let i 7\n"
                                   "/include part{i}.f2\n"
                                   "/include \"part7.f2\" x\n"
                                   "/include \"\"\n"
                                   "/include part{1/0}.f2\n");
    const ParseResult r = parseSceneFile(main);
    std::vector<std::string> lines;
    for (const Diagnostic& d : r.diagnostics) lines.push_back(d.format());
    EXPECT_EQ(lines, (std::vector<std::string>{
                         main + ":3:21: error: unexpected text after the quoted path of '/include'",
                         main + ":4:10: error: empty path in '/include'",
                         main + ":5:16: error: division by zero",
                     }));
    EXPECT_EQ(r.files, (std::vector<std::string>{main, path("part7.f2")}));
}

TEST_F(Include, AllFilesTogetherRespectTheSceneSize) {
    const std::string big = write("big.f2", std::string(50, '#') + "\n");
    const std::string main = write("main.f2", "/include big.f2\n");  // 16 bytes
    ParseLimits limits;
    limits.maxSceneBytes = 60;
    const ParseResult r = parseSceneFile(main, limits);
    ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r);
    EXPECT_EQ(r.diagnostics[0].format(),
              main + ":1:10: error: cannot include '" + big +
                  "': the file is 51 bytes, more than the limit of 44 bytes (for all "
                  "the files of the scene together)");
    limits.maxSceneBytes = 67;
    EXPECT_TRUE(parseSceneFile(main, limits).ok());
}

TEST_F(Include, CyclesAreErrors) {
    const std::string a = write("a.f2", "/sphere a 1 0 0 0\n/include b.f2\n");
    write("b.f2", "\n\n/include a.f2\n");
    const ParseResult r = parseSceneFile(a);
    ASSERT_EQ(r.diagnostics.size(), 1u) << dump(r);
    EXPECT_EQ(r.diagnostics[0].format(), path("b.f2") + ":3:10: error: include cycle: '" + a + "' -> '" +
                                             path("b.f2") + "' -> '" + a + "'");
    const std::string self = write("self.f2", "/include self.f2\n");
    const ParseResult s = parseSceneFile(self);
    ASSERT_EQ(s.diagnostics.size(), 1u) << dump(s);
    EXPECT_NE(s.diagnostics[0].message.find("include cycle"), std::string::npos);
}

TEST_F(Include, TheSameFileTwiceIsNoCycle) {
    write("ball.f2", "/sphere ball{k} 1 (k) 0 0\n");
    const std::string main =
        write("main.f2", "/repeat k 1 3\n/include ball.f2\n/end\n/let k 9\n/include ball.f2\n");
    const ParseResult r = parseSceneFile(main);
    ASSERT_TRUE(r.ok()) << dump(r);
    EXPECT_EQ(names(*r.scene), (std::vector<std::string>{"ball1", "ball2", "ball3", "ball9"}));
    EXPECT_EQ(r.files.size(), 2u);
}

TEST_F(Include, NestingDeeperThan16IsAnError) {
    for (int i = 0; i < 18; ++i)
        write("f" + std::to_string(i) + ".f2", "/include f" + std::to_string(i + 1) + ".f2\n");
    write("f18.f2", "/sphere deep 1 0 0 0\n");
    const ParseResult r = parseSceneFile(path("f2.f2"));  // 16 includes below f2.f2: fine
    EXPECT_TRUE(r.ok()) << dump(r);
    const ParseResult deep = parseSceneFile(path("f1.f2"));
    ASSERT_EQ(deep.diagnostics.size(), 1u) << dump(deep);
    EXPECT_EQ(deep.diagnostics[0].format(),
              path("f17.f2") + ":1:10: error: includes are nested more than 16 deep");
}

TEST_F(Include, LoopsDoNotCrossFiles) {
    write("opens.f2", "/repeat i 0 1\n");
    write("closes.f2", "/end\n");
    const std::string main = write("main.f2", "/include opens.f2\n/repeat j 0 1\n/include closes.f2\n/end\n");
    const ParseResult r = parseSceneFile(main);
    std::vector<std::string> lines;
    for (const Diagnostic& d : r.diagnostics) lines.push_back(d.format());
    EXPECT_EQ(lines, (std::vector<std::string>{
                         path("opens.f2") + ":1:1: error: '/repeat' without '/end' in the same file",
                         path("closes.f2") +
                             ":1:1: error: '/end' without '/repeat' (in /repeat j = 0) (and in 1 more pass)",
                     }));
}

TEST_F(Include, StandardInputIncludesFromTheCurrentDirectory) {
    write("here.f2", "/sphere here 1 0 0 0\n");
    const fs::path before = fs::current_path();
    fs::current_path(dir_);
    const ParseResult r = parseScene("/include here.f2\n", "<stdin>");
    fs::current_path(before);
    ASSERT_TRUE(r.ok()) << dump(r);
    EXPECT_EQ(names(*r.scene), (std::vector<std::string>{"here"}));
}

}  // namespace
}  // namespace f2
