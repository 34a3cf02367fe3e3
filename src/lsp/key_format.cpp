// textDocument/formatting: a run of consecutive `/key` lines is aligned into
// columns (numbers right-aligned, words left-aligned, comments in one column).
// Nothing else is touched.
#include <algorithm>

#include "core/parse/lexer.h"
#include "lsp/features.h"

namespace f2::lsp {

namespace {

struct KeyLine {
    int index = 0;  ///< 0-based line
    std::vector<std::string_view> tokens;
    std::string_view comment;  ///< from '#', trailing blanks removed; may be empty
};

bool isNumeric(std::string_view token) {
    const char c = token.front();
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == '(';
}

std::optional<KeyLine> keyLine(const TextDocument& doc, int index) {
    const std::string_view line = doc.line(index);
    LineTokens tokens;
    tokenizeLine(line, tokens);
    if (tokens.count == 0 || tokens.count > kMaxStoredTokens || tokens.tokens[0].text != "/key") {
        return std::nullopt;
    }
    KeyLine k;
    k.index = index;
    for (int i = 0; i < tokens.count; ++i)
        k.tokens.push_back(tokens.tokens[static_cast<std::size_t>(i)].text);
    const Token& last = tokens.tokens[static_cast<std::size_t>(tokens.count - 1)];
    const std::size_t after = static_cast<std::size_t>(last.column - 1) + last.text.size();
    if (const std::size_t hash = line.find('#', after); hash != std::string_view::npos) {
        k.comment = line.substr(hash);
        while (!k.comment.empty() && (k.comment.back() == ' ' || k.comment.back() == '\t')) {
            k.comment.remove_suffix(1);
        }
    }
    return k;
}

std::string pad(std::string_view token, std::size_t width, bool right) {
    const std::string fill(width > token.size() ? width - token.size() : 0, ' ');
    return right ? fill + std::string(token) : std::string(token) + fill;
}

/// Aligned text of each line of a run; `indent` is the first line's.
std::vector<std::string> alignRun(const std::vector<KeyLine>& run, std::string_view indent) {
    std::vector<std::size_t> widths;
    for (const KeyLine& k : run) {
        if (widths.size() < k.tokens.size()) widths.resize(k.tokens.size(), 0);
        for (std::size_t i = 0; i < k.tokens.size(); ++i) widths[i] = std::max(widths[i], k.tokens[i].size());
    }
    std::vector<std::string> lines;
    std::size_t longest = 0;
    for (const KeyLine& k : run) {
        std::string text(indent);
        for (std::size_t i = 0; i < k.tokens.size(); ++i) {
            if (i > 0) text += ' ';
            const bool last = i + 1 == k.tokens.size();
            const bool right = isNumeric(k.tokens[i]);
            // The last word of a line is not padded (no trailing blanks) unless numbers right-align.
            text += last && !right ? std::string(k.tokens[i]) : pad(k.tokens[i], widths[i], right);
        }
        longest = std::max(longest, text.size());
        lines.push_back(std::move(text));
    }
    for (std::size_t i = 0; i < run.size(); ++i) {
        if (run[i].comment.empty()) continue;
        lines[i] += std::string(longest - lines[i].size() + 2, ' ');
        lines[i] += run[i].comment;
    }
    return lines;
}

}  // namespace

Json formatKeys(const Analysis& a) {
    Json edits = Json::array();
    const TextDocument& doc = a.document;
    int i = 0;
    while (i < doc.lineCount()) {
        std::vector<KeyLine> run;
        while (i < doc.lineCount()) {
            auto k = keyLine(doc, i);
            if (!k) break;
            run.push_back(std::move(*k));
            ++i;
        }
        if (run.empty()) {
            ++i;
            continue;
        }
        if (run.size() < 2) continue;
        const std::string_view first = doc.line(run.front().index);
        const std::string_view indent = first.substr(0, first.find_first_not_of(" \t"));
        const std::vector<std::string> aligned = alignRun(run, indent);
        for (std::size_t k = 0; k < run.size(); ++k) {
            if (doc.line(run[k].index) == aligned[k]) continue;
            edits.push_back({{"range", toJson(doc.lineRange(run[k].index))}, {"newText", aligned[k]}});
        }
    }
    return edits;
}

}  // namespace f2::lsp
