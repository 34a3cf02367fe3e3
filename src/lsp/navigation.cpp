// Go to definition, find references and rename of object names (every place
// the parser saw the name) and of variables (every place the text has it), in
// this document, the files it includes and an open file that includes it.
#include <cstdint>
#include <map>
#include <set>
#include <tuple>

#include "core/parse/language.h"
#include "lsp/features.h"

namespace f2::lsp {

namespace {

/// A name's place in the text, for sets of unique places (a name inside a
/// loop is seen once per pass).
using Place = std::tuple<std::string, int, int>;

Place placeOf(const TokenSpan& s) { return {s.loc.file, s.loc.line, s.loc.column}; }

/// Every place of an object's name: its definition first, then its uses in file order.
std::vector<TokenSpan> occurrences(const Analysis& a, std::size_t object, bool includeDefinition) {
    std::vector<TokenSpan> out;
    std::set<Place> seen;
    auto add = [&](const TokenSpan& s) {
        if (seen.insert(placeOf(s)).second) out.push_back(s);
    };
    if (includeDefinition) add(a.index.objects[object].name);
    for (const NameUse& use : a.index.uses) {
        if (use.object == object) add(use.name);
    }
    return out;
}

Json locationOf(const Analysis& a, const TokenSpan& s) {
    return location(a.uriOf(s.loc.file), a.anyRangeOf(s));
}

/// The object under the cursor (its name, or the name before `.part`).
std::optional<std::size_t> objectAt(const Analysis& a, Position p) {
    const SymbolAt at = symbolAt(a, p);
    if (at.kind != SymbolAt::Kind::Object) return std::nullopt;
    return at.object;
}

const SceneFile& fileOf(const Analysis& a, const VariableOccurrence& v) {
    return a.sources.files[static_cast<std::size_t>(v.file)];
}

Json locationOf(const Analysis& a, const VariableOccurrence& v) {
    const SceneFile& file = fileOf(a, v);
    const std::string_view line = file.document.line(v.line);
    return location(a.uriOf(file.path), {{v.line, utf16Length(line.substr(0, v.begin))},
                                         {v.line, utf16Length(line.substr(0, v.end))}});
}

/// Every place of a variable in the scene's files, in reading order, each once
/// (an included file read twice lists its lines twice).
std::vector<const VariableOccurrence*> variableOccurrences(const Analysis& a, const std::string& name) {
    std::vector<const VariableOccurrence*> out;
    std::set<std::tuple<int, int, std::size_t>> seen;
    for (const VariableOccurrence& v : a.sources.variables) {
        if (v.name == name && seen.insert({v.file, v.line, v.begin}).second) out.push_back(&v);
    }
    return out;
}

/// References of the variable under the cursor, in reading order.
Json variableReferences(const Analysis& a, const std::string& name, bool includeDeclaration) {
    Json out = Json::array();
    for (const VariableOccurrence* v : variableOccurrences(a, name)) {
        if (includeDeclaration || !v->definition) out.push_back(locationOf(a, *v));
    }
    return out;
}

/// A WorkspaceEdit from locations, one TextEdit array per URI.
Json workspaceEdit(const std::vector<Json>& locations, const std::string& newName) {
    std::map<std::string, Json> edits;  // uri -> TextEdit array
    for (const Json& loc : locations) {
        edits[loc["uri"].get<std::string>()].push_back({{"range", loc["range"]}, {"newText", newName}});
    }
    Json changes = Json::object();
    for (auto& [uri, list] : edits) changes[uri] = std::move(list);
    return {{"changes", std::move(changes)}};
}

Json renameVariable(const Analysis& a, const std::string& name, const std::string& newName) {
    if (newName == "pi") throw RequestError(kRequestFailed, "'pi' is predefined and cannot be a variable");
    if (newName != name && definitionOf(a.sources.variables, newName, ~std::uint32_t{0})) {
        throw RequestError(kRequestFailed, "a variable named '" + newName + "' already exists");
    }
    std::vector<Json> places;
    for (const VariableOccurrence* v : variableOccurrences(a, name)) places.push_back(locationOf(a, *v));
    return workspaceEdit(places, newName);
}

}  // namespace

Json definition(const Analysis& a, Position p) {
    const SymbolAt at = symbolAt(a, p);
    if (at.kind == SymbolAt::Kind::Variable) {
        const auto def = definitionOf(a.sources.variables, at.text, a.sources.orderOf(a.self, p.line));
        return def ? locationOf(a, *def) : Json();
    }
    if (at.kind == SymbolAt::Kind::Include) {
        return location(uriFromPath(resolveInclude(a.path, at.text)), Range{});
    }
    const auto object = objectAt(a, p);
    if (!object) return nullptr;
    return locationOf(a, a.index.objects[*object].name);
}

Json references(const Analysis& a, Position p, bool includeDeclaration) {
    if (const SymbolAt at = symbolAt(a, p); at.kind == SymbolAt::Kind::Variable) {
        return variableReferences(a, at.text, includeDeclaration);
    }
    const auto object = objectAt(a, p);
    if (!object) return nullptr;
    Json out = Json::array();
    for (const TokenSpan& s : occurrences(a, *object, includeDeclaration)) out.push_back(locationOf(a, s));
    return out;
}

Json prepareRename(const Analysis& a, Position p) {
    const SymbolAt at = symbolAt(a, p);
    if (at.kind == SymbolAt::Kind::Variable) return {{"range", toJson(at.range)}, {"placeholder", at.text}};
    if (at.kind != SymbolAt::Kind::Object) return nullptr;
    return {{"range", toJson(at.range)}, {"placeholder", a.index.objects[at.object].object.name}};
}

Json rename(const Analysis& a, Position p, const std::string& newName) {
    if (!isValidName(newName)) {
        throw RequestError(kInvalidParams, "'" + newName +
                                               "' is not a valid name (a letter or '_', then letters, digits "
                                               "or '_')");
    }
    if (const SymbolAt at = symbolAt(a, p); at.kind == SymbolAt::Kind::Variable) {
        return renameVariable(a, at.text, newName);
    }
    const auto object = objectAt(a, p);
    if (!object) throw RequestError(kRequestFailed, "there is no object or variable name here to rename");
    const std::string& oldName = a.index.objects[*object].object.name;
    if (newName == "camera") {
        throw RequestError(kRequestFailed, "'camera' names the scene camera and cannot be an object's name");
    }
    if (newName != oldName && findObject(a.index, newName)) {
        throw RequestError(kRequestFailed, "an object named '" + newName + "' already exists");
    }
    std::vector<Json> places;
    for (const TokenSpan& s : occurrences(a, *object, true)) {
        // A name built by an expression (`r{i}`) is not the old name in the text.
        if (const TextDocument* text = a.textOf(s.loc.file)) {
            const Range r = a.anyRangeOf(s);
            const std::string_view line = text->line(r.start.line);
            const long begin = text->byteInLine(r.start);
            if (begin < 0 ||
                line.substr(static_cast<std::size_t>(begin), static_cast<std::size_t>(s.length)) != oldName) {
                throw RequestError(kRequestFailed, "'" + oldName + "' is written as an expression at " +
                                                       (a.inDocument(s.loc) ? "" : s.loc.file + " ") +
                                                       "line " + std::to_string(s.loc.line) +
                                                       "; rename it by hand");
            }
        }
        places.push_back(locationOf(a, s));
    }
    return workspaceEdit(places, newName);
}

}  // namespace f2::lsp
