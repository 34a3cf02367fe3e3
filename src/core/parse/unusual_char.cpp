#include "core/parse/unusual_char.h"

#include <array>
#include <cstdint>
#include <cstdio>

#include "core/parse/lexer.h"

namespace f2 {

namespace {

/// What to tell the user about a character, besides its name.
enum class Hint { None, Space, Invisible, Minus, Bom, CarriageReturn };

struct NamedCharacter {
    std::uint32_t code;
    std::string_view name;
    Hint hint;
};

/// The characters people meet by accident: copied from web pages, word
/// processors and PDFs, or typed by "smart" keyboards. Sorted by code.
constexpr std::array<NamedCharacter, 36> kNamed = {{
    {0x0000, "NULL", Hint::Invisible},
    {0x000B, "LINE TABULATION (vertical tab)", Hint::Space},
    {0x000C, "FORM FEED", Hint::Space},
    {0x000D, "CARRIAGE RETURN", Hint::CarriageReturn},
    {0x007F, "DELETE", Hint::Invisible},
    {0x0085, "NEXT LINE", Hint::Space},
    {0x00A0, "NO-BREAK SPACE", Hint::Space},
    {0x00AD, "SOFT HYPHEN", Hint::Invisible},
    {0x2002, "EN SPACE", Hint::Space},
    {0x2003, "EM SPACE", Hint::Space},
    {0x2007, "FIGURE SPACE", Hint::Space},
    {0x2008, "PUNCTUATION SPACE", Hint::Space},
    {0x2009, "THIN SPACE", Hint::Space},
    {0x200A, "HAIR SPACE", Hint::Space},
    {0x200B, "ZERO WIDTH SPACE", Hint::Invisible},
    {0x200C, "ZERO WIDTH NON-JOINER", Hint::Invisible},
    {0x200D, "ZERO WIDTH JOINER", Hint::Invisible},
    {0x200E, "LEFT-TO-RIGHT MARK", Hint::Invisible},
    {0x200F, "RIGHT-TO-LEFT MARK", Hint::Invisible},
    {0x2010, "HYPHEN", Hint::Minus},
    {0x2011, "NON-BREAKING HYPHEN", Hint::Minus},
    {0x2012, "FIGURE DASH", Hint::Minus},
    {0x2013, "EN DASH", Hint::Minus},
    {0x2014, "EM DASH", Hint::Minus},
    {0x2018, "LEFT SINGLE QUOTATION MARK", Hint::None},
    {0x2019, "RIGHT SINGLE QUOTATION MARK", Hint::None},
    {0x201C, "LEFT DOUBLE QUOTATION MARK", Hint::None},
    {0x201D, "RIGHT DOUBLE QUOTATION MARK", Hint::None},
    {0x202F, "NARROW NO-BREAK SPACE", Hint::Space},
    {0x205F, "MEDIUM MATHEMATICAL SPACE", Hint::Space},
    {0x2060, "WORD JOINER", Hint::Invisible},
    {0x2212, "MINUS SIGN", Hint::Minus},
    {0x3000, "IDEOGRAPHIC SPACE", Hint::Space},
    {0xFE63, "SMALL HYPHEN-MINUS", Hint::Minus},
    {0xFEFF, "ZERO WIDTH NO-BREAK SPACE", Hint::Bom},
    {0xFF0D, "FULLWIDTH HYPHEN-MINUS", Hint::Minus},
}};

std::string_view hintText(Hint hint) {
    switch (hint) {
        case Hint::None:
            return "";
        case Hint::Space:
            return ", which does not separate tokens: only spaces and tabs do";
        case Hint::Invisible:
            return ", an invisible character: delete it";
        case Hint::Minus:
            return ", which is not a minus: write '-'";
        case Hint::Bom:
            return ", a byte order mark, allowed only at the very start of the file";
        case Hint::CarriageReturn:
            return ", which ends a line only just before a line feed";
    }
    return "";
}

bool isOrdinary(std::uint8_t b) { return (b > 0x20 && b < 0x7F) || b == ' ' || b == '\t'; }

}  // namespace

namespace {

/// The character at text[i], which is not ordinary: its name and what to do.
UnusualCharacter describe(std::string_view text, std::size_t i) {
    const auto b = static_cast<std::uint8_t>(text[i]);
    char code[16];
    if (text.substr(i).starts_with("\xFF\xFE") || text.substr(i).starts_with("\xFE\xFF")) {
        return {"bytes " + std::string(b == 0xFF ? "0xFF 0xFE" : "0xFE 0xFF"),
                "a UTF-16 byte order mark: save the file as UTF-8"};
    }
    const Utf8Char d = decodeUtf8(text, i);
    if (d.bytes == 0) {
        std::snprintf(code, sizeof code, "0x%02X", static_cast<unsigned>(b));
        return {"byte " + std::string(code), "which is not UTF-8 text"};
    }
    std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(d.code));
    for (const NamedCharacter& c : kNamed) {
        if (c.code == d.code) {
            std::string_view hint = hintText(c.hint);
            if (!hint.empty()) hint.remove_prefix(2);  // ", "
            return {std::string(code) + " " + std::string(c.name), std::string(hint)};
        }
    }
    if (d.code < 0x20 || (d.code >= 0x7F && d.code < 0xA0)) return {code, "a control character"};
    return {code, "but commands, names and numbers are plain ASCII"};
}

}  // namespace

std::string unusualCharacterNote(std::string_view text, int column) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (isOrdinary(static_cast<std::uint8_t>(text[i]))) continue;
        const UnusualCharacter c = describe(text, i);
        const bool bytes = c.name.starts_with("byte");  // "the byte 0xE9", "U+00A0 NO-BREAK SPACE"
        return "it contains " + std::string(bytes ? "the " : "") + c.name + " at column " +
               std::to_string(column + static_cast<int>(i)) + (c.hint.empty() ? "" : ", " + c.hint);
    }
    return {};
}

std::optional<UnusualCharacter> unusualCharacterAt(std::string_view text) {
    if (text.empty() || isOrdinary(static_cast<std::uint8_t>(text[0]))) return std::nullopt;
    return describe(text, 0);
}

std::string withUnusualCharacterNote(std::string message, std::string_view text, int column) {
    const std::string note = unusualCharacterNote(text, column);
    if (note.empty()) return message;
    if (message.ends_with(')')) {
        message.insert(message.size() - 1, (message.ends_with("?)") ? " " : "; ") + note);
        return message;
    }
    return message + " (" + note + ")";
}

}  // namespace f2
