// publishDiagnostics: the parser's errors and warnings with the range of what
// they point at, grouped by file (a scene's includes have their own),
// and on each `/include` line of the document a summary of the problems in
// the files it reads, which an editor shows even when those files are closed.
#include <filesystem>
#include <map>

#include "lsp/features.h"

namespace f2::lsp {

namespace {

/// At most this many related places in an include line's summary.
constexpr std::size_t kMaxRelated = 20;

/// The `/include` of this document through which `file` is read, or null.
const IncludeLink* includeFor(const Analysis& a, const std::string& file) {
    const int target = a.sources.find(file);
    if (target < 0) return nullptr;
    for (const IncludeLink& link : a.sources.includes) {
        if (link.file == a.self && link.target >= 0 && a.sources.reaches(link.target, target)) return &link;
    }
    return nullptr;
}

/// What the diagnostic marks: the same bytes the viewer underlines (core markedBytes).
Range markedRange(const TextDocument& doc, const Diagnostic& d) {
    const ByteSpan span = markedBytes(d, doc.line(d.loc.line - 1));
    return doc.range(d.loc.line, static_cast<int>(span.first) + 1, static_cast<int>(span.length));
}

struct IncludeSummary {
    int errors = 0, warnings = 0;
    std::string first;  ///< the first problem, "part.f2:3:8: message"
    Json related = Json::array();
};

}  // namespace

Json publishDiagnostics(const Analysis& a) {
    std::map<std::string, Json> byFile;  // path -> Diagnostic array
    const TextDocument unread;
    std::map<const IncludeLink*, IncludeSummary> summaries;  // by include of this document
    byFile[a.path] = Json::array();
    for (const Diagnostic& d : a.result.diagnostics) {
        // The parser places every problem in a file it read (a missing include's on the include line).
        const TextDocument* doc = a.textOf(d.loc.file);
        if (!doc) doc = &unread;
        const Range range = markedRange(*doc, d);
        Json& list = byFile[d.loc.file];
        if (list.is_null()) list = Json::array();
        list.push_back({{"range", toJson(range)},
                        {"severity", d.severity == Severity::Error ? kSeverityError : kSeverityWarning},
                        {"source", "f2"},
                        {"message", d.message}});
        if (a.inDocument(d.loc)) continue;
        const IncludeLink* include = includeFor(a, d.loc.file);
        if (!include) continue;
        IncludeSummary& s = summaries[include];
        (d.severity == Severity::Error ? s.errors : s.warnings) += 1;
        const std::string shortName = std::filesystem::path(d.loc.file)
                                          .lexically_relative(std::filesystem::path(a.path).parent_path())
                                          .string();
        if (s.first.empty()) {
            s.first = shortName + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) +
                      ": " + d.message;
        }
        if (s.related.size() < kMaxRelated) {
            s.related.push_back({{"location", location(a.uriOf(d.loc.file), range)}, {"message", d.message}});
        }
    }
    Json& own = byFile[a.path];
    for (const auto& [include, s] : summaries) {
        const int line = include->line;
        const std::string_view text = a.document.line(line);
        const Range range{{line, utf16Length(text.substr(0, include->begin))},
                          {line, utf16Length(text.substr(0, include->end))}};
        const int more = s.errors + s.warnings - 1;
        std::string message = "in the included file " + s.first;
        if (more > 0)
            message += " (and " + std::to_string(more) + " more problem" + (more > 1 ? "s" : "") + ")";
        own.push_back({{"range", toJson(range)},
                       {"severity", s.errors > 0 ? kSeverityError : kSeverityWarning},
                       {"source", "f2"},
                       {"message", std::move(message)},
                       {"relatedInformation", s.related}});
    }
    Json result = Json::array();
    result.push_back({{"uri", a.uri}, {"version", a.document.version()}, {"diagnostics", own}});
    for (auto& [file, list] : byFile) {
        if (file != a.path) result.push_back({{"uri", a.uriOf(file)}, {"diagnostics", std::move(list)}});
    }
    return result;
}

}  // namespace f2::lsp
