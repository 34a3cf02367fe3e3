// Go to definition, find references and rename of object names: every place
// the parser saw the name, in this document and in the files it includes.
#include <map>
#include <set>
#include <tuple>

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
    if (a.inDocument(s.loc)) return location(a.uri, a.rangeOf(s));
    // In an included file: its lines are not loaded, and a name is on one line, so
    // the range is exact in bytes; ASCII names make bytes and UTF-16 units the same
    // unless the line has other characters before it (then the client clamps).
    const Range r{{s.loc.line - 1, s.loc.column - 1}, {s.loc.line - 1, s.loc.column - 1 + s.length}};
    return location(uriFromPath(s.loc.file), r);
}

/// The object under the cursor (its name, or the name before `.part`).
std::optional<std::size_t> objectAt(const Analysis& a, Position p) {
    const SymbolAt at = symbolAt(a, p);
    if (at.kind != SymbolAt::Kind::Object) return std::nullopt;
    return at.object;
}

Range rangeOf(const Analysis& a, const VariableOccurrence& v) {
    const std::string_view line = a.document.line(v.line);
    return {{v.line, utf16Length(line.substr(0, v.begin))}, {v.line, utf16Length(line.substr(0, v.end))}};
}

/// References of the variable under the cursor, in text order.
Json variableReferences(const Analysis& a, const std::string& name, bool includeDeclaration) {
    Json out = Json::array();
    for (const VariableOccurrence& v : a.variables) {
        if (v.name == name && (includeDeclaration || !v.definition))
            out.push_back(location(a.uri, rangeOf(a, v)));
    }
    return out;
}

Json renameVariable(const Analysis& a, const std::string& name, const std::string& newName) {
    if (newName == "pi") throw RequestError(kRequestFailed, "'pi' is predefined and cannot be a variable");
    if (newName != name && definitionOf(a.variables, newName, a.document.lineCount())) {
        throw RequestError(kRequestFailed, "a variable named '" + newName + "' already exists");
    }
    Json edits = Json::array();
    for (const VariableOccurrence& v : a.variables) {
        if (v.name == name) edits.push_back({{"range", toJson(rangeOf(a, v))}, {"newText", newName}});
    }
    return {{"changes", {{a.uri, std::move(edits)}}}};
}

}  // namespace

Json definition(const Analysis& a, Position p) {
    const SymbolAt at = symbolAt(a, p);
    if (at.kind == SymbolAt::Kind::Variable) {
        const auto def = definitionOf(a.variables, at.text, p.line);
        return def ? location(a.uri, rangeOf(a, *def)) : Json();
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
    if (newName != oldName && findObject(a.index, newName)) {
        throw RequestError(kRequestFailed, "an object named '" + newName + "' already exists");
    }
    std::map<std::string, Json> edits;  // uri -> TextEdit array
    for (const TokenSpan& s : occurrences(a, *object, true)) {
        // A name built by an expression (`r{i}`) is not the old name in the text.
        if (a.inDocument(s.loc)) {
            const std::string_view line = a.document.line(s.loc.line - 1);
            const Range r = a.rangeOf(s);
            const std::size_t begin = a.document.byteInLine(r.start);
            if (line.substr(begin, static_cast<std::size_t>(s.length)) != oldName) {
                throw RequestError(kRequestFailed, "'" + oldName + "' is written as an expression at line " +
                                                       std::to_string(s.loc.line) + "; rename it by hand");
            }
        }
        const Json loc = locationOf(a, s);
        edits[loc["uri"].get<std::string>()].push_back({{"range", loc["range"]}, {"newText", newName}});
    }
    Json changes = Json::object();
    for (auto& [uri, list] : edits) changes[uri] = std::move(list);
    return {{"changes", std::move(changes)}};
}

}  // namespace f2::lsp
