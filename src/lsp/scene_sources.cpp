#include "lsp/scene_sources.h"

#include <limits>
#include <map>

namespace f2::lsp {

namespace {

constexpr std::uint32_t kNotReached = std::numeric_limits<std::uint32_t>::max();

}  // namespace

SceneSources sourcesOf(const SymbolIndex& index) {
    SceneSources out;
    std::map<std::string_view, int> fileIndex;
    std::vector<std::size_t> bom;  // the parser's columns start after a byte order mark
    for (const IndexedFile& f : index.files) {
        fileIndex.emplace(f.path, static_cast<int>(out.files.size()));
        bom.push_back(std::string_view(f.text).starts_with("\xEF\xBB\xBF") ? 3 : 0);
        out.files.push_back({f.path, TextDocument(f.text, 0)});
        out.firstOrder.push_back(f.firstOrder);
    }
    // Where a token of the index is: its file and line, and its first byte in the line.
    struct Place {
        int file = -1, line = 0;
        std::size_t begin = 0;
    };
    auto placeOf = [&](const TokenSpan& span) {
        const auto it = fileIndex.find(span.loc.file);
        if (it == fileIndex.end()) return Place{};
        const std::size_t shift = span.loc.line == 1 ? bom[static_cast<std::size_t>(it->second)] : 0;
        return Place{it->second, span.loc.line - 1, shift + static_cast<std::size_t>(span.loc.column - 1)};
    };
    for (const IndexedVariable& v : index.variables) {
        const Place p = placeOf(v.span);
        if (p.file < 0) continue;
        out.variables.push_back({v.name, p.line, p.begin, p.begin + static_cast<std::size_t>(v.span.length),
                                 v.definition, v.loop, p.file, v.order, v.value});
    }
    for (const IndexedInclude& i : index.includes) {
        const Place p = placeOf(i.path);
        if (p.file < 0) continue;
        const auto target = fileIndex.find(i.target);
        out.includes.push_back({p.file, p.line, p.begin, p.begin + static_cast<std::size_t>(i.path.length),
                                i.read && target != fileIndex.end() ? target->second : -1, i.target});
    }
    return out;
}

int SceneSources::find(std::string_view path) const {
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (files[i].path == path) return static_cast<int>(i);
    }
    return -1;
}

std::uint32_t SceneSources::orderOf(int file, int line) const {
    if (file < 0 || static_cast<std::size_t>(file) >= firstOrder.size()) return kNotReached;
    const auto& lines = firstOrder[static_cast<std::size_t>(file)];
    for (auto i = std::min(line, static_cast<int>(lines.size()) - 1); i >= 0; --i) {
        if (lines[static_cast<std::size_t>(i)] != IndexedFile::kNotRead)
            return lines[static_cast<std::size_t>(i)];
    }
    return kNotReached;
}

bool SceneSources::reaches(int from, int to) const {
    if (from == to) return true;
    return to >= 0 && static_cast<std::size_t>(to) < files.size() &&
           reachableFrom(from)[static_cast<std::size_t>(to)];
}

std::vector<bool> SceneSources::reachableFrom(int from) const {
    std::vector<bool> seen(files.size(), false);
    if (from < 0 || static_cast<std::size_t>(from) >= files.size()) return seen;
    std::vector<std::vector<int>> targets(files.size());
    for (const IncludeLink& l : includes) {
        if (l.target >= 0) targets[static_cast<std::size_t>(l.file)].push_back(l.target);
    }
    std::vector<int> todo{from};
    seen[static_cast<std::size_t>(from)] = true;
    while (!todo.empty()) {
        const int f = todo.back();
        todo.pop_back();
        for (const int t : targets[static_cast<std::size_t>(f)]) {
            if (!seen[static_cast<std::size_t>(t)]) {
                seen[static_cast<std::size_t>(t)] = true;
                todo.push_back(t);
            }
        }
    }
    return seen;
}

std::optional<VariableOccurrence> definitionOf(const std::vector<VariableOccurrence>& all,
                                               std::string_view name, std::uint32_t order) {
    std::optional<VariableOccurrence> first, nearest;
    for (const VariableOccurrence& o : all) {
        if (!o.definition || o.name != name) continue;
        if (!first) first = o;
        if (o.order <= order) nearest = o;
    }
    return nearest ? nearest : first;
}

}  // namespace f2::lsp
