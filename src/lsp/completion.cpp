// textDocument/completion: commands (as snippets) and the scene's model types
// as commands, object names, parts after `name.` and shapes after
// `name.part.`, interpolation modes and key properties, `camera`; inside a
// `/model` block its commands, parts and shapes — what fits the argument
// under the cursor.
#include <algorithm>
#include <filesystem>

#include "core/parse/expression.h"
#include "core/parse/language.h"
#include "core/parse/lexer.h"
#include "core/scene/models.h"
#include "core/scene/scene_desc.h"
#include "lsp/features.h"
#include "lsp/model_types.h"

namespace f2::lsp {

namespace {

/// At most this many object names in one answer (a scene may have a million).
constexpr std::size_t kMaxNameItems = 1000;

/// The token being typed: its index on the line and its text up to the cursor.
struct Typing {
    int index = 0;             ///< 0 = the command word
    std::string_view partial;  ///< the token's bytes before the cursor
    std::size_t begin = 0;     ///< byte where the token starts
    std::string_view command;  ///< token 0 of the line
};

std::optional<Typing> typingAt(std::string_view line, std::size_t byte) {
    const std::string_view before = line.substr(0, byte);
    if (before.find('#') != std::string_view::npos) return std::nullopt;  // in a comment
    LineTokens tokens;
    tokenizeLine(before, tokens);
    Typing t;
    const bool afterSpace = before.empty() || before.back() == ' ' || before.back() == '\t';
    if (tokens.count > kMaxStoredTokens) return std::nullopt;
    if (afterSpace || tokens.count == 0) {
        t.index = tokens.count;
        t.begin = byte;
    } else {
        const Token& last = tokens.tokens[static_cast<std::size_t>(tokens.count - 1)];
        t.index = tokens.count - 1;
        t.partial = last.text;
        t.begin = static_cast<std::size_t>(last.column - 1);
    }
    if (tokens.count > 0) t.command = tokens.tokens[0].text;
    return t;
}

Json item(std::string_view label, int kind, std::string_view detail, const Range& replace,
          std::string_view newText, bool snippet = false) {
    Json j = {{"label", label},
              {"kind", kind},
              {"detail", detail},
              {"textEdit", {{"range", toJson(replace)}, {"newText", newText}}}};
    if (snippet) j["insertTextFormat"] = kInsertSnippet;
    return j;
}

/// Objects created before line `beforeLine` (1-based) of this document, or in other files.
std::vector<const IndexedObject*> visibleObjects(const Analysis& a, int beforeLine) {
    std::vector<const IndexedObject*> out;
    for (const IndexedObject& o : a.index.objects) {
        if (!a.inDocument(o.name.loc) || o.name.loc.line < beforeLine) out.push_back(&o);
    }
    return out;
}

/// The key properties (SPEC 10.3) a `/key` target has, judged from its text:
/// the camera its zoom, a named light its intensity, a shape (`name.part.shape`)
/// and anything else its colour and visibility.
bool hasProperty(const Analysis& a, std::string_view target, KeyProperty property) {
    if (target == kCameraName) return property == KeyProperty::Zoom;
    if (findLight(a.index, target)) return property == KeyProperty::Intensity;
    return property == KeyProperty::Colour || property == KeyProperty::Visible;
}

/// `colour ${1:255} ${2:255} ${3:255}`, `intensity …`, `d …`: the key properties of `target`.
void addKeyProperties(Json& items, const Analysis& a, std::string_view target, const Range& replace) {
    for (const KeyPropertySpec& p : keyProperties()) {
        if (!hasProperty(a, target, p.property)) continue;
        std::string snippet(p.word);
        for (int k = 0; k < p.numbers; ++k)
            snippet += " ${" + std::to_string(k + 1) + ":" + (p.numbers == 3 ? "255" : "1") + "}";
        items.push_back(item(p.word, kCompletionField,
                             "key property (" + std::string(p.values) + ") of " + std::string(p.targets),
                             replace, snippet, true));
    }
}

void addModes(Json& items, const Range& replace) {
    for (Interpolation mode : interpolationModes()) {
        const std::string_view word = interpolationName(mode);
        if (modeNumberCount(mode) == 0) {
            items.push_back(item(word, kCompletionEnumMember, "interpolation mode", replace, word));
            continue;
        }
        // `bezier x1 y1 x2 y2`: CSS's `ease` curve as the placeholders.
        std::string snippet(word);
        const char* kPlaceholders[] = {"0.25", "0.1", "0.25", "1"};
        for (int k = 0; k < modeNumberCount(mode); ++k)
            snippet += " ${" + std::to_string(k + 1) + ":" + kPlaceholders[k % 4] + "}";
        items.push_back(
            item(word, kCompletionEnumMember, "interpolation mode (x1 y1 x2 y2)", replace, snippet, true));
    }
}

void addParts(Json& items, const Analysis& a, std::string_view objectName, const Range& replace,
              std::string_view prefix, int beforeLine) {
    for (const IndexedObject* o : visibleObjects(a, beforeLine)) {
        if (o->object.name != objectName || !o->object.model) continue;
        for (const ModelPart& part : o->object.model->parts) {
            const std::string text = std::string(prefix) + part.name;
            items.push_back(item(text, kCompletionField,
                                 "part of " + o->object.model->name + " " + o->object.name, replace, text));
        }
        return;
    }
}

/// A `/drive`'s channels that `target` has (SPEC 10.7): the pose's, then
/// `d` for the camera, `intensity` for a named light, `r g b` for the others.
void addChannels(Json& items, const Analysis& a, std::string_view target, const Range& replace) {
    const std::string_view name = target.substr(0, target.find('.'));
    const bool camera = name == kCameraName;
    const bool light = std::any_of(a.index.lights.begin(), a.index.lights.end(),
                                   [&](const IndexedLight& l) { return l.name == name; });
    for (std::string_view word : driveChannelNames()) {
        const DriveChannel c = *driveChannelFromWord(word);
        const bool pose = c < DriveChannel::Intensity;
        const bool fits = pose || (c == DriveChannel::D && camera) ||
                          (c == DriveChannel::Intensity && light) ||
                          (c >= DriveChannel::R && !camera && !light);
        if (!fits) continue;
        const std::string detail = pose                           ? "drive a number of the pose"
                                   : c == DriveChannel::D         ? "drive the camera's d"
                                   : c == DriveChannel::Intensity ? "drive the light's intensity"
                                                                  : "drive a colour channel (0..255)";
        items.push_back(item(word, kCompletionField, detail, replace, word));
    }
}

/// After `name.part.`: the shapes of that part (SPEC 10.1), which take looks and colour keys.
void addShapes(Json& items, const Analysis& a, std::string_view objectName, std::string_view partName,
               const Range& replace, std::string_view prefix, int beforeLine) {
    for (const IndexedObject* o : visibleObjects(a, beforeLine)) {
        if (o->object.name != objectName || !o->object.model) continue;
        const ModelType& model = *o->object.model;
        const int part = model.partIndex(partName);
        for (const ModelShape& shape : model.shapes) {
            if (part < 0 || shape.part != part) continue;
            const std::string text = std::string(prefix) + shape.name;
            items.push_back(
                item(text, kCompletionField,
                     std::string(shapeKindName(shape.kind)) + " of " + model.name + " " + o->object.name,
                     replace, text));
        }
        return;
    }
}

/// After `/`: the scene's model types defined above (or in other files), as
/// commands that make an instance.
void addModelCommands(Json& items, const Analysis& a, const Range& replace, int beforeLine) {
    for (const IndexedModel& m : a.index.models) {
        if (!m.type || (a.inDocument(m.command) && m.command.line >= beforeLine)) continue;
        const std::string word = "/" + m.type->name;
        Json j = item(word, kCompletionClass, word + " <name> <px> <py> <pz> [<rx> <ry> <rz>]", replace,
                      word + " ${1:name} ${2:0} ${3:0} ${4:0}", true);
        std::string parts;
        for (const ModelPart& part : m.type->parts) parts += (parts.empty() ? "" : ", ") + part.name;
        j["documentation"] = {
            {"kind", "markdown"},
            {"value", "An instance of the model `" + m.type->name + "` (parts " + parts + ")."}};
        items.push_back(std::move(j));
    }
}

/// After an instance's position (`/lamp L1 0 0 0 `): its type's parameters
/// not yet given on the line, each with its default (SPEC 10.6).
void addModelParameters(Json& items, const Analysis& a, std::string_view line, const Typing& typing,
                        const Range& replace, int beforeLine) {
    constexpr int kFirstOption = 5;  // the command, the name and three numbers come first
    if (typing.index < kFirstOption || !typing.command.starts_with('/')) return;
    LineTokens tokens;
    tokenizeLine(line, tokens);
    for (const IndexedModel& m : a.index.models) {
        if (!m.type || m.type->name != typing.command.substr(1)) continue;
        if (a.inDocument(m.command) && m.command.line >= beforeLine) continue;
        for (const ModelParam& param : m.type->params) {
            const bool given = std::any_of(tokens.tokens.begin() + kFirstOption,
                                           tokens.tokens.begin() + std::min(tokens.count, kMaxStoredTokens),
                                           [&](const Token& t) { return t.text == param.name; });
            if (given || !param.name.starts_with(typing.partial)) continue;
            const std::string value = formatNumber(param.value);
            items.push_back(item(param.name, kCompletionProperty,
                                 "parameter of " + m.type->name + " (default " + value + ")", replace,
                                 param.name + " ${1:" + value + "}", true));
        }
        return;
    }
}

/// The commands that may stand inside a `/model` block (SPEC 10.1), their
/// first argument a shape of the model.
Json blockCommandItems(const Range& replace) {
    using enum CommandId;
    static constexpr CommandId kInBlock[] = {Part,    Sphere, Cylinder, Box,    Paint,  Material,
                                             Checker, End,    Let,      Repeat, Include};
    Json items = Json::array();
    for (CommandId id : kInBlock) {
        const CommandSpec& doc = command(id);
        std::string snippet(doc.snippet);
        for (std::string_view placeholder : {"${1:name}", "${1:target}"}) {
            if (const std::size_t at = snippet.find(placeholder); at != std::string::npos)
                snippet.replace(at, placeholder.size(), "${1:part.shape}");
        }
        Json j = item(doc.name, kCompletionKeyword, doc.syntax, replace, snippet, true);
        j["documentation"] = {{"kind", "markdown"}, {"value", std::string(doc.meaning)}};
        items.push_back(std::move(j));
    }
    return items;
}

/// An argument inside a `/model` block: a `/part`'s parent, a shape's
/// `part.` and the shapes that looks name. Nothing when another kind of
/// argument is typed (the caller goes on).
std::optional<Json> blockArgumentItems(const ModelBlock& block, const CommandSpec& doc, int arg,
                                       const Range& replace) {
    Json items = Json::array();
    auto add = [&](const std::string& text, std::string_view detail) {
        items.push_back(item(text, kCompletionField, detail, replace, text));
    };
    const std::string of = " of " + block.type;
    switch (doc.id) {
        case CommandId::Part:
            if (arg != 1) return std::nullopt;
            add(std::string(kRootName), "the model's own frame");
            for (const std::string& part : block.parts) add(part, "part" + of);
            return items;
        case CommandId::Sphere:
        case CommandId::Cylinder:
        case CommandId::Box:
            if (arg != 0) return std::nullopt;
            for (const std::string& part : block.parts) add(part + ".", "a shape on the part " + part + of);
            return items;
        case CommandId::Paint:
        case CommandId::Material:
        case CommandId::Checker:
            if (arg != 0) return std::nullopt;
            for (const std::string& shape : block.shapes) add(shape, "shape" + of);
            return items;
        default:
            return std::nullopt;
    }
}

/// Inside `( … )` or `{ … }`: the variables defined above, pi and the functions;
/// in a `/drive`'s expression also `frame` and `time` (SPEC 10.7).
Json expressionItems(const Analysis& a, Position p, std::string_view line, std::size_t byte, bool drive) {
    std::size_t begin = byte;
    while (begin > 0 && isNameChar(line[begin - 1])) --begin;  // the language's name rule, not the locale's
    const Range replace{{p.line, utf16Length(line.substr(0, begin))}, p};
    Json items = Json::array();
    std::vector<std::string> seen;
    const std::uint32_t here = a.sources.orderOf(a.self, p.line);
    for (const VariableOccurrence& v : a.sources.variables) {
        if (!v.definition || v.order > here || std::find(seen.begin(), seen.end(), v.name) != seen.end())
            continue;
        seen.push_back(v.name);
        const std::string& file = a.sources.files[static_cast<std::size_t>(v.file)].path;
        std::string where = "line " + std::to_string(v.line + 1);
        if (v.file != a.self) where += " of " + std::filesystem::path(file).filename().string();
        items.push_back(item(v.name, kCompletionVariable, (v.loop ? "loop variable, " : "variable, ") + where,
                             replace, v.name));
    }
    items.push_back(item("pi", kCompletionVariable, "3.14159…", replace, "pi"));
    if (drive) {
        items.push_back(item(kDriveInputs[0], kCompletionVariable,
                             "the frame drawn (fractional in motion blur)", replace, kDriveInputs[0]));
        items.push_back(
            item(kDriveInputs[1], kCompletionVariable, "frame / fps, in seconds", replace, kDriveInputs[1]));
    }
    for (std::string_view f : expressionFunctionNames()) {
        const std::string_view detail = f == "atan2" ? "atan2(y, x), degrees"
                                        : f == "if"  ? "if(condition, a, b): a if condition is not 0, else b"
                                                     : "function";
        items.push_back(item(f, kCompletionFunction, detail, replace, std::string(f) + "($1)", true));
    }
    return items;
}

/// The argument of `/include`: directories and .f2 files next to the typed path.
Json includeItems(const Analysis& a, Position p, std::string_view partial, std::size_t begin) {
    namespace fs = std::filesystem;
    const bool quoted = partial.starts_with('"');
    const std::string_view typed = quoted ? partial.substr(1) : partial;
    const std::size_t slash = typed.rfind('/');
    const std::string_view directory = slash == std::string_view::npos ? "" : typed.substr(0, slash + 1);
    const std::string_view rest = slash == std::string_view::npos ? typed : typed.substr(slash + 1);
    const std::size_t restBegin = begin + partial.size() - rest.size();
    const std::string_view line = a.document.line(p.line);
    const Range replace{{p.line, utf16Length(line.substr(0, restBegin))}, p};
    Json items = Json::array();
    std::error_code ec;
    const fs::path where = resolveInclude(a.path, directory.empty() ? "." : directory);
    constexpr int kMaxEntries = 200;
    int count = 0;
    for (fs::directory_iterator it(where, ec), end; !ec && it != end && count < kMaxEntries;
         it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.starts_with('.')) continue;
        std::error_code typeError;
        if (it->is_directory(typeError)) {
            items.push_back(item(name + "/", kCompletionFile, "directory", replace, name + "/"));
        } else if (it->path().extension() == ".f2" && it->path() != fs::path(a.path)) {
            items.push_back(item(name, kCompletionFile, "scene file", replace, name));
        } else {
            continue;
        }
        ++count;
    }
    return items;
}

}  // namespace

Json completion(const Analysis& a, Position p) {
    Json items = Json::array();
    const long byteLong = a.document.byteInLine(p);
    if (byteLong < 0) return items;
    const std::string_view line = a.document.line(p.line);
    const auto typing = typingAt(line, static_cast<std::size_t>(byteLong));
    if (!typing) return items;
    const Range replace{{p.line, utf16Length(line.substr(0, typing->begin))}, p};
    if (typing->index > 0 && insideExpression(line, static_cast<std::size_t>(byteLong))) {
        const bool drive = typing->command == command(CommandId::Drive).name;
        return expressionItems(a, p, line, static_cast<std::size_t>(byteLong), drive);
    }

    const int lineNumber = p.line + 1;
    const std::optional<ModelBlock> block = modelBlockAt(a.document, p.line);
    if (typing->index == 0) {
        if (block) return blockCommandItems(replace);
        for (const CommandSpec& doc : commands()) {
            Json j = item(doc.name, kCompletionKeyword, doc.syntax, replace, doc.snippet, true);
            j["documentation"] = {{"kind", "markdown"}, {"value", std::string(doc.meaning)}};
            items.push_back(std::move(j));
        }
        addModelCommands(items, a, replace, lineNumber);
        return items;
    }
    const CommandSpec* doc = findCommand(typing->command);
    if (!doc) {
        addModelParameters(items, a, line, *typing, replace, lineNumber);
        return items;
    }
    const int arg = typing->index - 1;
    const ArgKind kind = doc->argumentKind(arg);
    if (block) {
        if (auto inBlock = blockArgumentItems(*block, *doc, arg, replace)) return std::move(*inBlock);
    }

    // After `name.`: the parts of that model; after `name.part.`: that part's shapes.
    const std::size_t dot = typing->partial.find('.');
    if (dot != std::string_view::npos && (kind == ArgKind::Target || kind == ArgKind::PointOrTarget)) {
        const std::string_view name = typing->partial.substr(0, dot);
        if (const std::size_t second = typing->partial.find('.', dot + 1); second != std::string_view::npos) {
            addShapes(items, a, name, typing->partial.substr(dot + 1, second - dot - 1), replace,
                      typing->partial.substr(0, second + 1), lineNumber);
        } else {
            addParts(items, a, name, replace, typing->partial.substr(0, dot + 1), lineNumber);
        }
        return items;
    }
    switch (kind) {
        case ArgKind::Target:
        case ArgKind::Object:
        case ArgKind::PointOrTarget:
            // Names that start as typed; a huge scene gives a first part of them,
            // marked incomplete, and the client asks again as the user types on.
            for (const IndexedObject* o : visibleObjects(a, lineNumber)) {
                if (!o->object.name.starts_with(typing->partial)) continue;
                if (items.size() == kMaxNameItems) {
                    return {{"isIncomplete", true}, {"items", std::move(items)}};
                }
                items.push_back(item(o->object.name, kCompletionVariable, objectKindName(o->object.kind),
                                     replace, o->object.name));
            }
            // The commands that take the camera take named lights (SPEC 10.2) too.
            if (doc->cameraArgument() == arg) {
                for (const IndexedLight& l : a.index.lights) {
                    if (a.inDocument(l.nameSpan.loc) && l.nameSpan.loc.line >= lineNumber) continue;
                    if (!l.name.starts_with(typing->partial)) continue;
                    items.push_back(
                        item(l.name, kCompletionVariable, "light (" + l.command + ")", replace, l.name));
                }
            }
            if (doc->cameraArgument() == arg && kCameraName.starts_with(typing->partial)) {
                items.push_back(item("camera", kCompletionKeyword, "the scene camera", replace, "camera"));
            }
            break;
        case ArgKind::Part:
            if (arg == 1 && doc->id == CommandId::Anim) {
                LineTokens tokens;
                tokenizeLine(line, tokens);
                if (tokens.count > 1) addParts(items, a, tokens.tokens[1].text, replace, "", lineNumber);
            }
            break;
        case ArgKind::Mode:
            addModes(items, replace);
            break;
        case ArgKind::Number:
            // A /key may end with a mode after the target or after the six numbers.
            // …or a property word (SPEC 10.3) and its values.
            // A shape takes no pose, so no mode after it (SPEC 10.1).
            if (doc->id == CommandId::Key && arg == 2) {
                LineTokens tokens;
                tokenizeLine(line, tokens);
                const std::string_view target = tokens.tokens[2].text;
                if (std::count(target.begin(), target.end(), '.') < 2) addModes(items, replace);
                addKeyProperties(items, a, target, replace);
            }
            break;
        case ArgKind::Path:
            if (arg == 0) return includeItems(a, p, typing->partial, typing->begin);
            break;
        case ArgKind::Channel: {
            LineTokens tokens;
            tokenizeLine(line, tokens);
            if (tokens.count > 1) addChannels(items, a, tokens.tokens[1].text, replace);
            break;
        }
        case ArgKind::NewName:
        case ArgKind::Variable:
        case ArgKind::Text:
            break;
    }
    return items;
}

}  // namespace f2::lsp
