// textDocument/completion: commands (as snippets), object names, parts after
// `name.`, interpolation modes, `camera` — what fits the argument under the cursor.
#include <algorithm>

#include "core/parse/lexer.h"
#include "core/scene/scene_desc.h"
#include "lsp/command_docs.h"
#include "lsp/features.h"

namespace f2::lsp {

namespace {

/// The token being typed: its index on the line and its text up to the cursor.
struct Typing {
    int index = 0;               ///< 0 = the command word
    std::string_view partial;    ///< the token's bytes before the cursor
    std::size_t begin = 0;       ///< byte where the token starts
    std::string_view command;    ///< token 0 of the line
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

void addModes(Json& items, const Range& replace) {
    for (std::string_view mode : languageFeatures().modes) {
        items.push_back(item(mode, kCompletionEnumMember, "interpolation mode", replace, mode));
    }
}

void addParts(Json& items, const Analysis& a, std::string_view objectName, const Range& replace,
              std::string_view prefix, int beforeLine) {
    for (const IndexedObject* o : visibleObjects(a, beforeLine)) {
        if (o->object.name != objectName || !isModel(o->object.kind)) continue;
        for (const char* part : kPartNames) {
            const std::string text = std::string(prefix) + part;
            items.push_back(item(text, kCompletionField,
                                 std::string("part of ") + std::string(objectKindName(o->object.kind)) + " " +
                                     o->object.name,
                                 replace, text));
        }
        return;
    }
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
    const LanguageFeatures& language = languageFeatures();

    if (typing->index == 0) {
        for (const CommandDoc& doc : commandDocs()) {
            if (!language.knows(doc.name)) continue;
            Json j = item(doc.name, kCompletionKeyword, doc.syntax, replace, doc.snippet, true);
            j["documentation"] = {{"kind", "markdown"}, {"value", std::string(doc.meaning)}};
            items.push_back(std::move(j));
        }
        return items;
    }
    const CommandDoc* doc = findCommandDoc(typing->command);
    if (!doc) return items;
    const int arg = typing->index - 1;
    const ArgKind kind = argumentKind(*doc, arg);
    const int lineNumber = p.line + 1;

    // After `name.`: the parts of that model.
    const std::size_t dot = typing->partial.find('.');
    if (dot != std::string_view::npos &&
        (kind == ArgKind::Target || kind == ArgKind::PointOrTarget)) {
        const std::string_view name = typing->partial.substr(0, dot);
        addParts(items, a, name, replace, typing->partial.substr(0, dot + 1), lineNumber);
        return items;
    }
    switch (kind) {
        case ArgKind::Target:
        case ArgKind::Object:
        case ArgKind::PointOrTarget:
            for (const IndexedObject* o : visibleObjects(a, lineNumber)) {
                items.push_back(item(o->object.name, kCompletionVariable, objectKindName(o->object.kind), replace,
                                     o->object.name));
            }
            if (language.cameraTarget && doc->name != "/paint" && doc->name != "/material" &&
                doc->name != "/look_at") {
                items.push_back(item("camera", kCompletionKeyword, "the scene camera", replace, "camera"));
            }
            break;
        case ArgKind::Part:
            if (arg == 1) {
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
            if (doc->name == "/key" && arg == 2 && language.keyModes) addModes(items, replace);
            break;
        case ArgKind::NewName:
        case ArgKind::Variable:
        case ArgKind::Path:
            break;
    }
    return items;
}

}  // namespace f2::lsp
