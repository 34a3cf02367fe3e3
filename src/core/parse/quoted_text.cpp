#include "core/parse/quoted_text.h"

#include "core/parse/lexer.h"

namespace f2 {

QuotedText readQuotedText(std::string_view token) {
    QuotedText out;
    auto fail = [&](std::size_t offset, std::string message) {
        out.offset = offset;
        out.message = std::move(message);
        return out;
    };
    if (!token.starts_with('"')) return fail(0, "expected a text in double quotes, got " + quoteToken(token));
    std::size_t i = 1;
    for (; i < token.size() && token[i] != '"'; ++i) {
        if (token[i] == '\\' && i + 1 < token.size() && (token[i + 1] == '"' || token[i + 1] == '\\')) {
            out.text += token[++i];
            continue;
        }
        const Utf8Char c = decodeUtf8(token, i);
        if (c.bytes == 0) return fail(i, "the text is not valid UTF-8 here");
        out.text.append(token.substr(i, c.bytes));
        i += c.bytes - 1;
    }
    if (i == token.size()) return fail(0, "this '\"' has no closing '\"'");
    if (i + 1 < token.size()) return fail(i + 1, "unexpected text after the closing '\"'");
    out.ok = true;
    return out;
}

}  // namespace f2
