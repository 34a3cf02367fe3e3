// The language server's features in the module (docs/web.md): the page's
// editor asks for completion and hover through one call, answered from the
// same analysis `f2 lsp` makes (src/lsp), in the LSP's JSON shapes with UTF-16
// positions, which is what JavaScript strings count. The stdio transport and
// the server loop are not compiled here: the page is the only client.
#include <optional>
#include <string>
#include <string_view>

#include "lsp/analysis.h"
#include "lsp/features.h"
#include "lsp/language_files.h"

namespace {

using f2::lsp::Json;

struct LanguageModule {
    std::optional<f2::lsp::Analysis> analysis;  ///< of the text last given by "open"
    std::string text;                           ///< the returned JSON lives here until the next call
};

LanguageModule& languageModule() {
    static LanguageModule m;
    return m;
}

/// The word lists the TextMate grammar is generated from, by name.
Json languageLists() {
    Json lists = Json::object();
    for (std::string_view name : f2::lsp::languageListNames())
        lists[std::string(name)] = *f2::lsp::languageList(name);
    return lists;
}

/// params.position, {0, 0} where it is missing or not numbers (the module
/// has no exceptions to catch: nlohmann-json's type errors must not happen).
f2::lsp::Position positionOf(const Json& params) {
    const auto position = params.find("position");
    if (position == params.end() || !position->is_object()) return {};
    auto number = [&](const char* key) {
        const auto it = position->find(key);
        return it != position->end() && it->is_number_integer() ? it->get<int>() : 0;
    };
    return {number("line"), number("character")};
}

Json answer(std::string_view method, const Json& params) {
    LanguageModule& m = languageModule();
    if (method == "f2/languageLists") return languageLists();
    if (method == "open") {
        const auto text = params.find("text");
        if (text == params.end() || !text->is_string()) return {{"error", "open: no text"}};
        // The editor's text as an unsaved document: includes resolve against nothing.
        m.analysis =
            f2::lsp::analyze("untitled:scene.f2", f2::lsp::TextDocument(text->get<std::string>(), 0));
        return nullptr;
    }
    if (!m.analysis) return {{"error", "no document: call open first"}};
    if (method == "textDocument/completion") return f2::lsp::completion(*m.analysis, positionOf(params));
    if (method == "textDocument/hover") return f2::lsp::hover(*m.analysis, positionOf(params));
    return {{"error", "unknown method " + std::string(method)}};
}

}  // namespace

extern "C" {

/// One request: `method` ("open" {text}, "textDocument/completion" and
/// "textDocument/hover" {position: {line, character}}, "f2/languageLists")
/// with its params as JSON text. Returns the result as JSON text ({"error"}
/// for a bad request), valid until the next call.
const char* f2_lsp(const char* method, const char* params) {
    const Json parsed = Json::parse(params, nullptr, false);  // no exceptions: a bad text is discarded
    LanguageModule& m = languageModule();
    m.text = parsed.is_object() ? f2::lsp::dumpJson(answer(method, parsed))
                                : R"({"error":"params are not a JSON object"})";
    return m.text.c_str();
}

}  // extern "C"
