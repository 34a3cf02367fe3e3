#include "lsp/analysis.h"

#include <algorithm>

#include "core/parse/language.h"
#include "core/parse/lexer.h"
#include "core/scene/models.h"
#include "lsp/model_types.h"

namespace f2::lsp {

namespace {

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

bool contains(const TokenSpan& span, std::size_t lineIndex, std::size_t byte, std::size_t bomBytes) {
    if (span.loc.line != static_cast<int>(lineIndex) + 1) return false;
    const std::size_t begin = bomBytes + static_cast<std::size_t>(span.loc.column - 1);
    return byte >= begin && byte <= begin + static_cast<std::size_t>(span.length);
}

/// A part or a shape named inside the `/model` block around `p`, once the
/// parser has indexed that block (SPEC 10.1): a `/part`'s name or parent, or
/// either half of a `part.shape` argument.
template <typename RangeInLine>
bool modelMemberAt(const Analysis& a, Position p, std::size_t byte, const RangeInLine& rangeInLine,
                   SymbolAt& at) {
    const std::string_view line = a.document.line(p.line);
    LineTokens tokens;
    tokenizeLine(line, tokens);
    if (tokens.count < 2) return false;
    const CommandSpec* command = findCommand(tokens.tokens[0].text);
    if (!command) return false;
    const bool isPart = command->id == CommandId::Part;
    // The commands a `/model` block takes with a `part.shape` (SPEC 10.1).
    const bool namesShape = createsModelShape(command->id) || command->id == CommandId::Paint ||
                            command->id == CommandId::Material || command->id == CommandId::Checker;
    if (!isPart && !namesShape) return false;
    const auto block = modelBlockAt(a.document, p.line);
    if (!block) return false;
    const auto known = findModel(a, block->type);
    if (!known || !known->indexed || !a.inDocument(known->indexed->command) ||
        known->indexed->command.line != block->line + 1)
        return false;
    const ModelType& model = *known->type;
    auto on = [&](int token, std::size_t from, std::size_t length) {
        const auto begin = static_cast<std::size_t>(tokens.tokens[std::size_t(token)].column - 1) + from;
        return byte >= begin && byte <= begin + length ? std::optional(begin) : std::nullopt;
    };
    auto set = [&](SymbolAt::Kind kind, int part, int shape, std::size_t begin, std::size_t length) {
        at = {kind, 0, part, {}, rangeInLine(begin, begin + length), block->type, shape};
        return true;
    };
    if (isPart) {
        for (int token = 1; token <= 2 && token < tokens.count; ++token) {
            const std::string_view word = tokens.tokens[std::size_t(token)].text;
            const int part = model.partIndex(word);
            if (const auto begin = on(token, 0, word.size()); begin && part >= 0)
                return set(SymbolAt::Kind::ModelPart, part, -1, *begin, word.size());
        }
        return false;
    }
    const std::string_view word = tokens.tokens[1].text;
    const std::size_t dot = word.find('.');
    if (dot == std::string_view::npos) return false;
    const int part = model.partIndex(word.substr(0, dot));
    if (part < 0) return false;
    if (const auto begin = on(1, 0, dot)) return set(SymbolAt::Kind::ModelPart, part, -1, *begin, dot);
    const std::string_view shapeName = word.substr(dot + 1);
    const int shape = model.shapeIndex(part, shapeName);
    if (const auto begin = on(1, dot + 1, shapeName.size()); begin && shape >= 0)
        return set(SymbolAt::Kind::ModelShape, part, shape, *begin, shapeName.size());
    return false;
}

}  // namespace

std::string pathFromUri(std::string_view uri) {
    constexpr std::string_view kFile = "file://";
    if (!uri.starts_with(kFile)) return std::string(uri);
    std::string_view rest = uri.substr(kFile.size());
    // "file://host/path": only the local host (empty or "localhost") is meaningful.
    if (rest.starts_with("localhost/")) rest.remove_prefix(9);
    std::string path;
    for (std::size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == '%' && i + 2 < rest.size()) {
            const int hi = hexValue(rest[i + 1]), lo = hexValue(rest[i + 2]);
            if (hi >= 0 && lo >= 0) {
                path += static_cast<char>(hi * 16 + lo);
                i += 2;
                continue;
            }
        }
        path += rest[i];
    }
    return path;
}

std::string uriFromPath(std::string_view path) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string uri = "file://";
    for (char c : path) {
        const auto b = static_cast<unsigned char>(c);
        // RFC 3986's unreserved characters (ASCII only, whatever the locale) and '/'.
        const bool unreserved = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                                c == '-' || c == '_' || c == '.' || c == '~';
        if (unreserved || c == '/') {
            uri += c;
        } else {
            uri += '%';
            uri += kHex[b >> 4];
            uri += kHex[b & 15];
        }
    }
    return uri;
}

Analysis analyze(std::string uri, TextDocument document, const SourceOverlay& open, const std::string& root) {
    Analysis a;
    a.path = pathFromUri(uri);
    a.uri = std::move(uri);
    a.document = std::move(document);
    if (const auto rootText = open.find(root); !root.empty() && root != a.path && rootText != open.end()) {
        // This document's own text stands for its file in the including scene
        // (a copy of the texts only when they hold another one: a server's do not).
        const auto own = open.find(a.path);
        SourceOverlay withThis;
        if (own == open.end() || own->second != a.document.text()) {
            withThis = open;
            withThis[a.path] = a.document.text();
        }
        const SourceOverlay& texts = withThis.empty() ? open : withThis;
        a.sources = scanScene(root, TextDocument(rootText->second, 0), texts);
        a.self = a.sources.find(a.path);
        if (a.self >= 0) {
            a.root = root;
            a.result = parseScene(rootText->second, root, ParseLimits{}, a.index, texts);
            return a;
        }
    }
    a.root = a.path;
    a.result = parseScene(a.document.text(), a.path, ParseLimits{}, a.index, open);
    a.sources = scanScene(a.path, a.document, open);
    a.self = 0;
    return a;
}

std::string Analysis::uriOf(std::string_view file) const {
    if (file == path) return uri;
    if (openUris) {
        if (std::optional<std::string> open = openUris->find(file)) return std::move(*open);
    }
    return uriFromPath(file);
}

std::optional<std::string> OpenUris::find(std::string_view path) const {
    const std::lock_guard lock(mutex_);
    const auto it = uris_.find(path);
    if (it == uris_.end()) return std::nullopt;
    return it->second;
}

void OpenUris::set(const std::string& path, const std::string& uri) {
    const std::lock_guard lock(mutex_);
    uris_[path] = uri;
}

void OpenUris::erase(const std::string& path) {
    const std::lock_guard lock(mutex_);
    uris_.erase(path);
}

const TextDocument* Analysis::textOf(std::string_view file) const {
    if (file == path) return &document;
    const int i = sources.find(file);
    return i < 0 ? nullptr : &sources.files[static_cast<std::size_t>(i)].document;
}

Range Analysis::anyRangeOf(const TokenSpan& span) const {
    if (const TextDocument* text = textOf(span.loc.file))
        return text->range(span.loc.line, span.loc.column, span.length);
    const int line = span.loc.line - 1, column = span.loc.column - 1;
    return {{line, column}, {line, column + span.length}};
}

std::vector<const VariableOccurrence*> Analysis::ownVariables() const {
    std::vector<const VariableOccurrence*> out;
    for (const VariableOccurrence& v : sources.variables) {
        // A file read twice (two includes) lists its lines twice: the first reading is enough.
        if (v.file == self && v.order == sources.orderOf(self, v.line)) out.push_back(&v);
    }
    return out;
}

std::optional<PartSuffix> partAfter(const Analysis& a, const TokenSpan& name, std::size_t object) {
    if (!a.inDocument(name.loc) || object >= a.index.objects.size()) return std::nullopt;
    const ModelType* model = a.index.objects[object].object.model.get();
    if (!model) return std::nullopt;
    const int lineIndex = name.loc.line - 1;
    const std::string_view line = a.document.line(lineIndex);
    const std::size_t bom = lineIndex == 0 && a.document.text().starts_with("\xEF\xBB\xBF") ? 3 : 0;
    const std::size_t dot = bom + static_cast<std::size_t>(name.loc.column - 1 + name.length);
    if (dot >= line.size() || line[dot] != '.') return std::nullopt;
    std::size_t end = dot + 1;
    while (end < line.size() && isNameChar(line[end])) ++end;
    const std::string_view word = line.substr(dot + 1, end - dot - 1);
    const int part = model->partIndex(word);
    if (part < 0) return std::nullopt;
    PartSuffix suffix{part, dot + 1, end};
    if (end < line.size() && line[end] == '.') {
        std::size_t shapeEnd = end + 1;
        while (shapeEnd < line.size() && isNameChar(line[shapeEnd])) ++shapeEnd;
        suffix.shape = model->shapeIndex(part, line.substr(end + 1, shapeEnd - end - 1));
        if (suffix.shape >= 0) {
            suffix.shapeBegin = end + 1;
            suffix.shapeEnd = shapeEnd;
        }
    }
    return suffix;
}

SymbolAt symbolAt(const Analysis& a, Position p) {
    SymbolAt at;
    const long byteLong = a.document.byteInLine(p);
    if (byteLong < 0) return at;
    const auto byte = static_cast<std::size_t>(byteLong);
    const auto lineIndex = static_cast<std::size_t>(p.line);
    const std::size_t bom = p.line == 0 && a.document.text().starts_with("\xEF\xBB\xBF") ? 3 : 0;

    const std::string_view lineText = a.document.line(p.line);
    auto rangeInLine = [&](std::size_t begin, std::size_t end) {
        return Range{{p.line, utf16Length(lineText.substr(0, begin))},
                     {p.line, utf16Length(lineText.substr(0, end))}};
    };
    auto onName = [&](const TokenSpan& span, std::size_t object) {
        if (!a.inDocument(span.loc) || !contains(span, lineIndex, byte, bom)) {
            // The part after `name.` belongs to the same object.
            if (a.inDocument(span.loc) && span.loc.line == p.line + 1) {
                const auto suffix = partAfter(a, span, object);
                if (suffix && byte >= suffix->begin && byte <= suffix->end) {
                    at = {SymbolAt::Kind::Part,
                          object,
                          suffix->part,
                          {},
                          rangeInLine(suffix->begin, suffix->end),
                          {}};
                    return true;
                }
                if (suffix && suffix->shape >= 0 && byte >= suffix->shapeBegin && byte <= suffix->shapeEnd) {
                    at = {SymbolAt::Kind::Shape,
                          object,
                          suffix->part,
                          {},
                          rangeInLine(suffix->shapeBegin, suffix->shapeEnd),
                          {},
                          suffix->shape};
                    return true;
                }
            }
            return false;
        }
        at = {SymbolAt::Kind::Object, object, -1, {}, a.rangeOf(span), {}};
        return true;
    };
    // A variable (also inside the braces of a name such as s{i}), or the path of an /include.
    for (const VariableOccurrence* v : a.ownVariables()) {
        if (v->line == p.line && byte >= v->begin && byte <= v->end) {
            at.kind = SymbolAt::Kind::Variable;
            at.range = rangeInLine(v->begin, v->end);
            at.text = v->name;
            return at;
        }
    }
    if (const auto include = includeOn(a.document, p.line);
        include && byte >= include->begin && byte <= include->end) {
        at.kind = SymbolAt::Kind::Include;
        at.range = rangeInLine(include->begin, include->end);
        at.text = include->path;
        return at;
    }

    // A light's name (SPEC 10.2): it has no parts.
    auto onLight = [&](const TokenSpan& span, std::size_t light) {
        if (!a.inDocument(span.loc) || !contains(span, lineIndex, byte, bom)) return false;
        at = {SymbolAt::Kind::Light, light, -1, {}, a.rangeOf(span), {}};
        return true;
    };
    for (std::size_t i = 0; i < a.index.objects.size(); ++i) {
        if (onName(a.index.objects[i].name, i)) return at;
    }
    for (std::size_t i = 0; i < a.index.lights.size(); ++i) {
        if (onLight(a.index.lights[i].nameSpan, i)) return at;
    }
    for (const NameUse& use : a.index.uses) {
        if (use.light ? onLight(use.name, use.object) : onName(use.name, use.object)) return at;
    }

    if (modelMemberAt(a, p, byte, rangeInLine, at)) return at;

    // A command word, or `camera` as an argument (SPEC 9.1: no object has that name).
    LineTokens tokens;
    tokenizeLine(a.document.line(p.line), tokens);
    for (int i = 1; i < std::min(tokens.count, kMaxStoredTokens); ++i) {
        const Token& t = tokens.tokens[static_cast<std::size_t>(i)];
        const auto begin = static_cast<std::size_t>(t.column - 1);
        if (t.text == "camera" && byte >= begin && byte <= begin + t.text.size()) {
            at.kind = SymbolAt::Kind::Camera;
            at.range = rangeInLine(begin, begin + t.text.size());
            return at;
        }
    }
    if (tokens.count > 0) {
        const Token& first = tokens.tokens[0];
        const std::size_t begin = static_cast<std::size_t>(first.column - 1);
        if (first.text.starts_with('/') && byte >= begin && byte <= begin + first.text.size()) {
            at.range = rangeInLine(begin, begin + first.text.size());
            // `/lamp l1 …`: an instance of a model type the scene defines (SPEC 10.1).
            if (!findCommand(first.text) && findModel(a, first.text.substr(1))) {
                at.kind = SymbolAt::Kind::Model;
                at.text = first.text.substr(1);
            } else {
                at.kind = SymbolAt::Kind::Command;
                at.command = first.text;
            }
            return at;
        }
        // The type's name after `/model`.
        if (first.text == "/model" && tokens.count > 1) {
            const Token& type = tokens.tokens[1];
            const auto typeBegin = static_cast<std::size_t>(type.column - 1);
            if (byte >= typeBegin && byte <= typeBegin + type.text.size()) {
                at.kind = SymbolAt::Kind::Model;
                at.text = type.text;
                at.range = rangeInLine(typeBegin, typeBegin + type.text.size());
            }
        }
    }
    return at;
}

std::optional<std::size_t> findObject(const SymbolIndex& index, std::string_view name) {
    for (std::size_t i = 0; i < index.objects.size(); ++i) {
        if (index.objects[i].object.name == name) return i;
    }
    return std::nullopt;
}

std::optional<std::size_t> findLight(const SymbolIndex& index, std::string_view name) {
    for (std::size_t i = 0; i < index.lights.size(); ++i) {
        if (index.lights[i].name == name) return i;
    }
    return std::nullopt;
}

std::vector<std::size_t> keyCounts(const Analysis& a, std::size_t object) {
    const SceneObject& indexed = a.index.objects[object].object;
    std::vector<std::size_t> counts(1 + (indexed.model ? indexed.model->parts.size() : 0), 0);
    if (a.result.ok() && object < a.result.scene->objects.size()) {
        const SceneObject& o = a.result.scene->objects[object];
        counts[0] = o.track.keys.size();
        for (std::size_t i = 0; i < o.partTracks.size() && i + 1 < counts.size(); ++i)
            counts[i + 1] = o.partTracks[i].keys.size();
        return counts;
    }
    for (const NameUse& use : a.index.uses) {
        if (use.light || use.object != object || use.command != "/key") continue;
        const auto suffix = partAfter(a, use.name, object);
        counts[suffix ? static_cast<std::size_t>(suffix->part + 1) : 0] += 1;
    }
    return counts;
}

}  // namespace f2::lsp
