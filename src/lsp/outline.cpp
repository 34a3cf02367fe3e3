// textDocument/documentSymbol (objects with their parts and key counts, model
// types with their parts, the camera, lights) and textDocument/foldingRange
// (`/repeat` and `/model` blocks).
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
    const std::vector<BlockLines> blocks = blocksOf(a.document);
    for (const IndexedModel& m : a.index.models) {
        if (!m.type || !a.inDocument(m.command)) continue;
        const int line = m.command.line - 1;
        // The whole block, so that its parts' lines are inside it.
        Range whole = a.document.lineRange(line);
        for (const BlockLines& b : blocks) {
            if (b.model && b.start == line) whole.end = a.document.lineRange(b.end).end;
        }
        Json parts = Json::array();
        for (std::size_t p = 0; p < m.type->parts.size() && p < m.parts.size(); ++p) {
            if (!a.inDocument(m.parts[p].loc)) continue;  // from an `/include` inside the block
            const ModelPart& part = m.type->parts[p];
            std::string detail = part.parent < 0 ? std::string("on root")
                                                 : "on " + m.type->parts[std::size_t(part.parent)].name;
            for (const ModelShape& shape : m.type->shapes) {
                if (shape.part == static_cast<int>(p)) detail += ", " + shape.name;
            }
            const Range selection = a.rangeOf(m.parts[p]);
            parts.push_back({{"name", part.name},
                             {"detail", std::move(detail)},
                             {"kind", kSymbolField},
                             {"range", toJson(a.document.lineRange(selection.start.line))},
                             {"selectionRange", toJson(selection)}});
        }
        entries.push_back({line,
                           {{"name", m.type->name},
                            {"detail", "model, " + std::to_string(m.type->parts.size()) + " parts, " +
                                           std::to_string(m.type->shapes.size()) + " shapes"},
                            {"kind", kSymbolClass},
                            {"range", toJson(whole)},
                            {"selectionRange", toJson(a.rangeOf(m.name))},
                            {"children", std::move(parts)}}});
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
    for (const BlockLines& b : blocksOf(a.document)) {
        // The fold keeps `/end` visible, as an editor keeps a closing bracket.
        if (b.closed && b.end - 1 > b.start)
            out.push_back({{"startLine", b.start}, {"endLine", b.end - 1}, {"kind", "region"}});
    }
    return out;
}

}  // namespace f2::lsp
