#pragma once
/// Lines and tokens of the scene language (SPEC 7): one command per line,
/// tokens separated by spaces or tabs, '#' to the end of the line is a comment.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace f2 {

/// One line of the source without its line end ("\n", "\r\n", or a lone
/// trailing "\r" at the end of the text).
struct SourceLine {
    std::string_view text;
    int number = 0;  ///< 1-based
};

/// Splits text into lines. A UTF-8 byte order mark at the very start is
/// skipped (columns on line 1 count from after it).
class LineReader {
   public:
    explicit LineReader(std::string_view text);
    /// False at the end of the text.
    bool next(SourceLine& line);

   private:
    std::string_view rest_;
    int number_ = 0;
    bool done_ = false;
};

struct Token {
    std::string_view text;
    int column = 0;  ///< 1-based byte column
};

/// The longest command has 18 tokens (/spot_light with its 9 arguments and
/// all three options, kMostLightArgs in the parser); a few more are stored so
/// that messages can quote them, the rest are only counted.
inline constexpr int kMaxStoredTokens = 20;

/// Tokens of one line; `count` may exceed kMaxStoredTokens (then only the
/// first kMaxStoredTokens are in `tokens`). No heap allocation.
struct LineTokens {
    std::array<Token, kMaxStoredTokens> tokens{};
    int count = 0;
};

/// Splits a line at spaces and tabs, stopping at the first '#'. Spaces inside
/// parentheses or braces do not split: "( 1 + 2 )" and "r{ i }" are one token
/// each (an unclosed one runs to the end of the line or the comment). A text
/// in double quotes is one token with its spaces and '#'s (`\"` inside it
/// does not close it); an unclosed one runs to the end of the line.
void tokenizeLine(std::string_view line, LineTokens& out);

/// One character decoded from UTF-8; `bytes` is 0 when s[i] does not start
/// a valid sequence (overlong forms and surrogates are invalid too).
struct Utf8Char {
    std::uint32_t code = 0;
    std::size_t bytes = 0;
};
Utf8Char decodeUtf8(std::string_view s, std::size_t i);

/// A token as it should appear inside a message: wrapped in single quotes,
/// control bytes and invalid UTF-8 written as \xNN, and cut after a few dozen
/// bytes, so that binary garbage never reaches a terminal raw.
std::string quoteToken(std::string_view token);

/// Like quoteToken() but never cut: a file path in "cannot read '...'" is
/// shown whole (it was cut after 48 bytes before, hiding which file it was).
std::string quotePath(std::string_view path);

/// Like quoteToken() but without the quotes (numbers in "got -1").
std::string printable(std::string_view token);

}  // namespace f2
