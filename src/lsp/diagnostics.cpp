// publishDiagnostics: the parser's errors and warnings with the range of the
// token they point at, grouped by file (a scene's includes have their own).
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "lsp/features.h"

namespace f2::lsp {

namespace {

/// The text of an included file, to turn its byte columns into positions.
TextDocument readDocument(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return TextDocument(std::move(text), 0);
}

}  // namespace

Json publishDiagnostics(const Analysis& a) {
    std::map<std::string, Json> byFile;  // path -> Diagnostic array
    std::map<std::string, TextDocument> others;
    byFile[a.path] = Json::array();
    for (const Diagnostic& d : a.result.diagnostics) {
        const TextDocument* doc = &a.document;
        if (!a.inDocument(d.loc)) {
            auto it = others.find(d.loc.file);
            if (it == others.end()) it = others.emplace(d.loc.file, readDocument(d.loc.file)).first;
            doc = &it->second;
        }
        Json& list = byFile[d.loc.file];
        if (list.is_null()) list = Json::array();
        list.push_back({{"range", toJson(doc->tokenRange(d.loc.line, d.loc.column))},
                        {"severity", d.severity == Severity::Error ? kSeverityError : kSeverityWarning},
                        {"source", "f2"},
                        {"message", d.message}});
    }
    Json result = Json::array();
    result.push_back({{"uri", a.uri}, {"version", a.document.version()}, {"diagnostics", byFile[a.path]}});
    for (auto& [file, list] : byFile) {
        if (file != a.path) result.push_back({{"uri", uriFromPath(file)}, {"diagnostics", std::move(list)}});
    }
    return result;
}

}  // namespace f2::lsp
