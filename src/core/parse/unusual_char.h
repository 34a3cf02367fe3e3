#pragma once
/// Names the invisible or look-alike characters that make a scene line wrong
/// although it looks right: a no-break space copied from a web page, a
/// zero-width space, a byte order mark in the middle of a file, a Unicode
/// minus or dash in a number.
#include <optional>
#include <string>
#include <string_view>

namespace f2 {

/// A note on the first character of `text` that is neither printable ASCII
/// nor a tab, for an error message: "it contains U+00A0 NO-BREAK SPACE at
/// column 8, which does not separate tokens: only spaces and tabs do".
/// `column` is the 1-based column of text[0] on its line. Empty if every
/// character is ordinary.
std::string unusualCharacterNote(std::string_view text, int column);

/// `message` with unusualCharacterNote(text, column) added in parentheses
/// (inside the message's own last parentheses, if it ends with one).
std::string withUnusualCharacterNote(std::string message, std::string_view text, int column);

/// An unusual character named: "U+00A0 NO-BREAK SPACE" and what to do about
/// it, "which does not separate tokens: only spaces and tabs do" (may be empty).
struct UnusualCharacter {
    std::string name;
    std::string hint;
};

/// The character at the start of `text` if it is neither printable ASCII nor
/// a space or tab (where an expression expected something else).
std::optional<UnusualCharacter> unusualCharacterAt(std::string_view text);

}  // namespace f2
