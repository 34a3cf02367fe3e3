// Go to definition, find references and rename of object names (every place
// the parser saw the name), of model types (their `/model` and instances) and
// of variables (every place the parser read it), in this document, the files it
// includes and an open file that includes it; definition of a model's parts
// and shapes (`name.part`, `name.part.shape`).
#include <cstdint>
#include <map>
#include <set>
#include <tuple>

#include "core/parse/language.h"
#include "lsp/features.h"
#include "lsp/model_types.h"

namespace f2::lsp {

namespace {

/// A name's place in the text, for sets of unique places (a name inside a
/// loop is seen once per pass).
using Place = std::tuple<std::string, int, int>;

Place placeOf(const TokenSpan& s) { return {s.loc.file, s.loc.line, s.loc.column}; }

/// An object or a named light (SPEC 10.2): the names the parser resolves.
struct Named {
    bool light = false;
    std::size_t index = 0;  ///< into index.objects, or index.lights when `light`
};

const TokenSpan& definitionOf(const Analysis& a, Named n) {
    return n.light ? a.index.lights[n.index].nameSpan : a.index.objects[n.index].name;
}

const std::string& nameOf(const Analysis& a, Named n) {
    return n.light ? a.index.lights[n.index].name : a.index.objects[n.index].object.name;
}

/// Every place of a name: its definition first, then its uses in file order.
std::vector<TokenSpan> occurrences(const Analysis& a, Named n, bool includeDefinition) {
    std::vector<TokenSpan> out;
    std::set<Place> seen;
    auto add = [&](const TokenSpan& s) {
        if (seen.insert(placeOf(s)).second) out.push_back(s);
    };
    if (includeDefinition) add(definitionOf(a, n));
    for (const NameUse& use : a.index.uses) {
        if (use.light == n.light && use.object == n.index) add(use.name);
    }
    return out;
}

Json locationOf(const Analysis& a, const TokenSpan& s) {
    return location(a.uriOf(s.loc.file), a.anyRangeOf(s));
}

/// The object (its name, or the name before `.part`) or light under the cursor.
std::optional<Named> namedAt(const Analysis& a, Position p) {
    const SymbolAt at = symbolAt(a, p);
    if (at.kind != SymbolAt::Kind::Object && at.kind != SymbolAt::Kind::Light) return std::nullopt;
    return Named{at.kind == SymbolAt::Kind::Light, at.object};
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

/// The definitions of a model type's name (the word after `/model`) and its
/// uses (`lamp` in each instance's `/lamp`), each place once; none for the
/// robot and the human, which no line defines.
std::vector<TokenSpan> modelOccurrences(const Analysis& a, const std::string& type, bool includeDefinition) {
    std::vector<TokenSpan> out;
    const auto known = findModel(a, type);
    if (!known || !known->indexed) return out;
    std::set<Place> seen;
    auto add = [&](const TokenSpan& s) {
        if (seen.insert(placeOf(s)).second) out.push_back(s);
    };
    if (includeDefinition) add(known->indexed->name);
    for (const IndexedObject& o : a.index.objects) {
        if (o.object.model.get() != known->type) continue;
        SourceLoc word = o.command;
        word.column += 1;  // after the '/'
        add({word, static_cast<int>(type.size())});
    }
    return out;
}

/// A `/part` or a shape of a model the scene defines, from a target
/// (`name.part`, `name.part.shape`) or from inside its block; nothing for the
/// robot's and the human's.
std::optional<TokenSpan> modelMemberDefinition(const Analysis& a, const SymbolAt& at) {
    const bool onTarget = at.kind == SymbolAt::Kind::Part || at.kind == SymbolAt::Kind::Shape;
    const auto known = onTarget ? std::nullopt : findModel(a, at.text);
    const IndexedModel* m = onTarget ? indexedModelOf(a, a.index.objects[at.object].object.model.get())
                            : known  ? known->indexed
                                     : nullptr;
    if (!m) return std::nullopt;
    const bool shape = at.kind == SymbolAt::Kind::Shape || at.kind == SymbolAt::Kind::ModelShape;
    const auto& spans = shape ? m->shapes : m->parts;
    const int member = shape ? at.shape : at.part;
    if (member < 0 || std::size_t(member) >= spans.size()) return std::nullopt;
    return spans[std::size_t(member)];
}

Json renameModel(const Analysis& a, const std::string& type, const std::string& newName) {
    if (findCommand("/" + newName) || newName == kRootName || newName == kCameraName) {
        throw RequestError(kRequestFailed,
                           "'" + newName + "' is a word of the language and cannot name a model");
    }
    if (newName != type && findModel(a, newName)) {
        throw RequestError(kRequestFailed, "a model named '" + newName + "' already exists");
    }
    const auto places = modelOccurrences(a, type, true);
    if (places.empty())
        throw RequestError(kRequestFailed, "'" + type + "' is built in and cannot be renamed");
    std::vector<Json> locations;
    for (const TokenSpan& s : places) locations.push_back(locationOf(a, s));
    return workspaceEdit(locations, newName);
}

}  // namespace

Json definition(const Analysis& a, Position p) {
    const SymbolAt at = symbolAt(a, p);
    if (at.kind == SymbolAt::Kind::Variable) {
        const auto def = definitionOf(a.sources.variables, at.text, a.sources.orderOf(a.self, p.line));
        return def ? locationOf(a, *def) : Json();
    }
    if (at.kind == SymbolAt::Kind::Include) {
        return location(uriFromPath(at.text), Range{});
    }
    if (at.kind == SymbolAt::Kind::Model) {
        const auto known = findModel(a, at.text);
        return known && known->indexed ? locationOf(a, known->indexed->name) : Json();
    }
    if (at.kind == SymbolAt::Kind::Part || at.kind == SymbolAt::Kind::Shape ||
        at.kind == SymbolAt::Kind::ModelPart || at.kind == SymbolAt::Kind::ModelShape) {
        const auto member = modelMemberDefinition(a, at);
        return member ? locationOf(a, *member) : Json();
    }
    const auto named = namedAt(a, p);
    if (!named) return nullptr;
    return locationOf(a, definitionOf(a, *named));
}

Json references(const Analysis& a, Position p, bool includeDeclaration) {
    const SymbolAt at = symbolAt(a, p);
    if (at.kind == SymbolAt::Kind::Variable) return variableReferences(a, at.text, includeDeclaration);
    if (at.kind == SymbolAt::Kind::Model) {
        Json out = Json::array();
        for (const TokenSpan& s : modelOccurrences(a, at.text, includeDeclaration))
            out.push_back(locationOf(a, s));
        return out;
    }
    const auto named = namedAt(a, p);
    if (!named) return nullptr;
    Json out = Json::array();
    for (const TokenSpan& s : occurrences(a, *named, includeDeclaration)) out.push_back(locationOf(a, s));
    return out;
}

Json prepareRename(const Analysis& a, Position p) {
    const SymbolAt at = symbolAt(a, p);
    if (at.kind == SymbolAt::Kind::Variable) return {{"range", toJson(at.range)}, {"placeholder", at.text}};
    if (at.kind == SymbolAt::Kind::Model) {
        if (const auto known = findModel(a, at.text); !known || !known->indexed) return nullptr;
        // On `/lamp` the name is the word without its '/'.
        Range range = at.range;
        if (range.end.character - range.start.character > static_cast<int>(at.text.size()))
            ++range.start.character;
        return {{"range", toJson(range)}, {"placeholder", at.text}};
    }
    const auto named = namedAt(a, p);
    if (!named) return nullptr;
    return {{"range", toJson(at.range)}, {"placeholder", nameOf(a, *named)}};
}

Json rename(const Analysis& a, Position p, const std::string& newName) {
    if (!isValidName(newName)) {
        throw RequestError(kInvalidParams, "'" + newName +
                                               "' is not a valid name (a letter or '_', then letters, digits "
                                               "or '_')");
    }
    if (const SymbolAt at = symbolAt(a, p); at.kind == SymbolAt::Kind::Variable) {
        return renameVariable(a, at.text, newName);
    } else if (at.kind == SymbolAt::Kind::Model) {
        return renameModel(a, at.text, newName);
    }
    const auto named = namedAt(a, p);
    if (!named)
        throw RequestError(kRequestFailed,
                           "there is no object, light, model or variable name here to rename");
    const std::string& oldName = nameOf(a, *named);
    if (newName == "camera") {
        throw RequestError(kRequestFailed, "'camera' names the scene camera and cannot be an object's name");
    }
    // Objects and named lights share one set of names (SPEC 10.2).
    if (newName != oldName && findObject(a.index, newName)) {
        throw RequestError(kRequestFailed, "an object named '" + newName + "' already exists");
    }
    if (newName != oldName && findLight(a.index, newName)) {
        throw RequestError(kRequestFailed, "a light named '" + newName + "' already exists");
    }
    std::vector<Json> places;
    for (const TokenSpan& s : occurrences(a, *named, true)) {
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
