#include "core/parse/lexer.h"

#include <cstdint>

namespace f2 {

namespace {
constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
/// Tokens quoted in messages are cut after this many bytes.
constexpr std::size_t kMaxQuotedBytes = 48;

void appendHex(std::string& out, std::uint8_t b) {
    constexpr char kHex[] = "0123456789abcdef";
    out += "\\x";
    out += kHex[b >> 4];
    out += kHex[b & 0xF];
}
}  // namespace

Utf8Char decodeUtf8(std::string_view s, std::size_t i) {
    const auto b0 = static_cast<std::uint8_t>(s[i]);
    if (b0 < 0x80) return {b0, 1};
    std::size_t len = 0;
    std::uint32_t cp = 0;
    if ((b0 & 0xE0) == 0xC0) {
        len = 2;
        cp = b0 & 0x1Fu;
    } else if ((b0 & 0xF0) == 0xE0) {
        len = 3;
        cp = b0 & 0x0Fu;
    } else if ((b0 & 0xF8) == 0xF0) {
        len = 4;
        cp = b0 & 0x07u;
    } else {
        return {};  // a continuation byte or 0xF8..0xFF cannot start a sequence
    }
    if (i + len > s.size()) return {};
    for (std::size_t k = 1; k < len; ++k) {
        const auto b = static_cast<std::uint8_t>(s[i + k]);
        if ((b & 0xC0) != 0x80) return {};
        cp = (cp << 6) | (b & 0x3Fu);
    }
    // Reject overlong forms, surrogates and values beyond U+10FFFF.
    constexpr std::uint32_t kMinForLength[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < kMinForLength[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return {};
    return {cp, len};
}

LineReader::LineReader(std::string_view text) : rest_(text) {
    if (rest_.starts_with(kUtf8Bom)) rest_.remove_prefix(kUtf8Bom.size());
}

bool LineReader::next(SourceLine& line) {
    if (done_) return false;
    const std::size_t nl = rest_.find('\n');
    std::string_view text;
    if (nl == std::string_view::npos) {
        // The last line; a text ending in '\n' has no extra empty line.
        done_ = true;
        if (rest_.empty()) return false;
        text = rest_;
        rest_ = {};
    } else {
        text = rest_.substr(0, nl);
        rest_.remove_prefix(nl + 1);
        if (rest_.empty()) done_ = true;
    }
    if (text.ends_with('\r')) text.remove_suffix(1);
    line.text = text;
    line.number = ++number_;
    return true;
}

void tokenizeLine(std::string_view line, LineTokens& out) {
    out.count = 0;
    std::size_t i = 0;
    const std::size_t n = line.size();
    while (i < n) {
        const char c = line[i];
        if (c == ' ' || c == '\t') {
            ++i;
            continue;
        }
        if (c == '#') break;  // comment to the end of the line
        const std::size_t start = i;
        // Inside ( ) and { } spaces do not split (SPEC 9.4: "( 1 + 2 )" is one
        // argument); '#' still starts a comment. Inside double quotes (a
        // caption's text, SPEC 10.5) neither spaces nor '#' end the token, and
        // \" does not close it.
        int depth = 0;
        bool quoted = false;
        while (i < n && (quoted || (line[i] != '#' && (depth > 0 || (line[i] != ' ' && line[i] != '\t'))))) {
            const char ch = line[i];
            if (quoted) {
                if (ch == '\\' && i + 1 < n)
                    ++i;  // \" and \\ stay inside
                else if (ch == '"')
                    quoted = false;
            } else if (ch == '"') {
                quoted = true;
            } else if (ch == '(' || ch == '{') {
                ++depth;
            } else if ((ch == ')' || ch == '}') && depth > 0) {
                --depth;
            }
            ++i;
        }
        if (out.count < kMaxStoredTokens) {
            out.tokens[static_cast<std::size_t>(out.count)] = {line.substr(start, i - start),
                                                               static_cast<int>(start) + 1};
        }
        ++out.count;
    }
}

namespace {
void appendPrintable(std::string& out, std::string_view token, std::size_t maxBytes = kMaxQuotedBytes) {
    const bool cut = token.size() > maxBytes;
    if (cut) token = token.substr(0, maxBytes);
    std::size_t i = 0;
    while (i < token.size()) {
        const auto b = static_cast<std::uint8_t>(token[i]);
        if (b == '\\') {
            out += "\\\\";
            ++i;
            continue;
        }
        const std::size_t len = b < 0x20 || b == 0x7F ? 0 : decodeUtf8(token, i).bytes;
        if (len == 0) {
            appendHex(out, b);
            ++i;
        } else {
            out.append(token.substr(i, len));
            i += len;
        }
    }
    if (cut) out += "...";
}
}  // namespace

std::string printable(std::string_view token) {
    std::string out;
    appendPrintable(out, token);
    return out;
}

std::string quoteToken(std::string_view token) {
    // Built by appending: GCC 12 warns falsely (-Wrestrict) on "'" + std::string.
    std::string out(1, '\'');
    appendPrintable(out, token);
    out += '\'';
    return out;
}

std::string quotePath(std::string_view path) {
    std::string out(1, '\'');
    appendPrintable(out, path, std::string_view::npos);
    out += '\'';
    return out;
}

}  // namespace f2
