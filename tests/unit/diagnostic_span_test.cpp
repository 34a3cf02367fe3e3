// The extent of a diagnostic (issue 23): the parser says how many bytes a
// problem covers, and markedBytes is the one rule by which the viewer
// underlines it and the language server ranges it.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "core/parse/diagnostic.h"
#include "core/parse/parser.h"

namespace f2 {
namespace {

/// The one diagnostic of `text`, a single line, and the bytes of it an editor marks.
struct Marked {
    Diagnostic diagnostic;
    std::string bytes;
};

Marked markedIn(std::string_view line) {
    const ParseResult r = parseScene(std::string(line) + "\n", "t.f2");
    EXPECT_EQ(r.diagnostics.size(), 1u) << line;
    if (r.diagnostics.empty()) return {};
    const Diagnostic& d = r.diagnostics.front();
    const ByteSpan span = markedBytes(d, line);
    return {d, std::string(line.substr(span.first, span.length))};
}

TEST(DiagnosticSpans, AnArgumentErrorCoversTheArgumentAsWritten) {
    const Marked number = markedIn("/sphere ball 1.5x 0 0 0");
    EXPECT_EQ(number.diagnostic.loc.column, 14);
    EXPECT_EQ(number.diagnostic.length, 4);
    EXPECT_EQ(number.bytes, "1.5x");
    // An expression with spaces in it is one argument: all of it, not up to its first space.
    const Marked expression = markedIn("/sphere b2 (1 - 3) 0 0 0");
    EXPECT_EQ(expression.diagnostic.message, "radius must be > 0, got -2");
    EXPECT_EQ(expression.bytes, "(1 - 3)");
}

TEST(DiagnosticSpans, ACommandErrorCoversTheCommandWord) {
    const Marked count = markedIn("/sphere b5 1 0 0  # short");
    EXPECT_EQ(count.diagnostic.loc.column, 1);
    EXPECT_EQ(count.bytes, "/sphere");
}

TEST(DiagnosticSpans, AnUnknownVariableCoversItsNameInsideTheExpression) {
    const Marked inParentheses = markedIn("/sphere b3 (1 + nope) 0 0 0");
    EXPECT_EQ(inParentheses.diagnostic.message, "unknown variable 'nope'");
    EXPECT_EQ(inParentheses.diagnostic.length, 4);
    EXPECT_EQ(inParentheses.bytes, "nope");  // not "nope)"
    const Marked inBraces = markedIn("/sphere b4{nope} 1 0 0 0");
    EXPECT_EQ(inBraces.bytes, "nope");  // not "nope}"
}

TEST(DiagnosticSpans, WithoutALengthTheTokenThereOrTheLinesEnd) {
    Diagnostic point;
    point.loc.column = 6;
    EXPECT_EQ(markedBytes(point, "/fps 24x # c").first, 5u);
    EXPECT_EQ(markedBytes(point, "/fps 24x # c").length, 3u);  // "24x": a space ends it
    EXPECT_EQ(markedBytes(point, "/fps 24x#c").length, 3u);    // and so does a comment
    point.loc.column = 5;  // just past "/fps": a missing argument marks the last byte
    EXPECT_EQ(markedBytes(point, "/fps").first, 3u);
    EXPECT_EQ(markedBytes(point, "/fps").length, 1u);
    point.loc.column = 90;  // beyond the line (the text changed since): still on it
    EXPECT_EQ(markedBytes(point, "/fps").first, 3u);
    EXPECT_EQ(markedBytes(point, "").length, 0u);
    Diagnostic spanned;
    spanned.loc.column = 3;
    spanned.length = 40;  // longer than the line: cut at its end
    EXPECT_EQ(markedBytes(spanned, "/fps 24").length, 5u);
}

}  // namespace
}  // namespace f2
