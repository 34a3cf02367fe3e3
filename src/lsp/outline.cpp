// textDocument/documentSymbol (objects with their parts and key counts, the
// camera, lights) and textDocument/foldingRange (`/repeat` … `/end` blocks).
#include <algorithm>

#include "core/parse/lexer.h"
#include "core/scene/models.h"
#include "lsp/features.h"

namespace f2::lsp {

namespace {

std::string keysText(std::size_t n) { return std::to_string(n) + (n == 1 ? " key" : " keys"); }

/// The arguments of a command line as written (after the command word, before any comment).
std::string argumentsText(std::string_view line) {
    LineTokens tokens;
    tokenizeLine(line, tokens);
    std::string out;
    const int stored = std::min(tokens.count, kMaxStoredTokens);
    for (int i = 1; i < stored; ++i) {
        if (!out.empty()) out += ' ';
        out += tokens.tokens[static_cast<std::size_t>(i)].text;
    }
    return out;
}

struct Entry {
    int line;  ///< 0-based, to sort
    Json symbol;
};

}  // namespace

Json documentSymbols(const Analysis& a) {
    std::vector<Entry> entries;
    for (std::size_t i = 0; i < a.index.objects.size(); ++i) {
        const IndexedObject& entry = a.index.objects[i];
        if (!a.inDocument(entry.name.loc)) continue;
        const SceneObject& o = entry.object;
        const auto keys = keyCounts(a, i);
        const Range selection = a.rangeOf(entry.name);
        const Range whole = a.document.lineRange(entry.command.line - 1);
        Json symbol = {{"name", o.name},
                       {"detail", std::string(typeNameOf(o)) + ", " + keysText(keys[0])},
                       {"kind", kSymbolObject},
                       {"range", toJson(whole)},
                       {"selectionRange", toJson(selection)}};
        if (o.model) {
            Json parts = Json::array();
            for (std::size_t p = 0; p < o.model->parts.size(); ++p) {
                parts.push_back({{"name", o.model->parts[p].name},
                                 {"detail", keysText(keys[p + 1])},
                                 {"kind", kSymbolField},
                                 {"range", toJson(whole)},
                                 {"selectionRange", toJson(selection)}});
            }
            symbol["children"] = std::move(parts);
        }
        entries.push_back({entry.command.line - 1, std::move(symbol)});
    }
    for (const IndexedCommand& c : a.index.commands) {
        if (!a.inDocument(c.loc)) continue;
        const int line = c.loc.line - 1;
        const bool camera = c.command == "/camera";
        const Range whole = a.document.lineRange(line);
        entries.push_back({line,
                           {{"name", camera ? std::string("camera") : c.command.substr(1)},
                            {"detail", argumentsText(a.document.line(line))},
                            {"kind", camera ? kSymbolConstant : kSymbolEvent},
                            {"range", toJson(whole)},
                            {"selectionRange", toJson(a.document.tokenRange(c.loc.line, c.loc.column))}}});
    }
    std::stable_sort(entries.begin(), entries.end(),
                     [](const Entry& x, const Entry& y) { return x.line < y.line; });
    Json out = Json::array();
    for (Entry& e : entries) out.push_back(std::move(e.symbol));
    return out;
}

Json foldingRanges(const Analysis& a) {
    Json out = Json::array();
    std::vector<int> open;  // lines of the `/repeat`s not closed yet
    LineTokens tokens;
    for (int i = 0; i < a.document.lineCount(); ++i) {
        tokenizeLine(a.document.line(i), tokens);
        if (tokens.count == 0) continue;
        const std::string_view command = tokens.tokens[0].text;
        if (command == "/repeat") {
            open.push_back(i);
        } else if (command == "/end" && !open.empty()) {
            const int start = open.back();
            open.pop_back();
            // The fold keeps `/end` visible, as an editor keeps a closing bracket.
            if (i - 1 > start) out.push_back({{"startLine", start}, {"endLine", i - 1}, {"kind", "region"}});
        }
    }
    return out;
}

}  // namespace f2::lsp
