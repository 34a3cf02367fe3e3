#include "lsp/source_scan.h"

#include <algorithm>
#include <filesystem>

#include "core/parse/language.h"

namespace f2::lsp {

namespace {

/// The line without its comment ('#' to the end; a quoted include path may hold '#').
std::string_view withoutComment(std::string_view line) {
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (line[i] == '"') quoted = !quoted;
        if (line[i] == '#' && !quoted) return line.substr(0, i);
    }
    return line;
}

/// First word of a line and where it ends; empty when the line has none.
std::string_view firstWord(std::string_view line, std::size_t& end) {
    std::size_t b = line.find_first_not_of(" \t");
    if (b == std::string_view::npos) return {};
    end = b;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t') ++end;
    return line.substr(b, end - b);
}

}  // namespace

std::vector<BlockLines> blocksOf(const TextDocument& doc) {
    std::vector<BlockLines> out, open;
    for (int i = 0; i < doc.lineCount(); ++i) {
        std::size_t wordEnd = 0;
        const std::string_view command = firstWord(withoutComment(doc.line(i)), wordEnd);
        if (command == "/repeat" || command == "/model") {
            open.push_back({i, i, command == "/model", false});
        } else if (command == "/end" && !open.empty()) {
            out.push_back({open.back().start, i, open.back().model, true});
            open.pop_back();
        }
    }
    while (!open.empty()) {
        out.push_back(
            {open.back().start, std::max(open.back().start, doc.lineCount() - 1), open.back().model, false});
        open.pop_back();
    }
    return out;
}

bool insideExpression(std::string_view line, std::size_t byte) {
    const std::string_view code = withoutComment(line);
    int depth = 0;
    for (std::size_t i = 0; i < std::min(byte, code.size()); ++i) {
        if (code[i] == '(' || code[i] == '{') ++depth;
        if ((code[i] == ')' || code[i] == '}') && depth > 0) --depth;
    }
    return depth > 0 && byte <= code.size();
}

std::string resolveInclude(std::string_view documentPath, std::string_view path) {
    namespace fs = std::filesystem;
    const fs::path p{std::string(path)};
    if (p.is_absolute()) return p.lexically_normal().string();
    return (fs::path(std::string(documentPath)).parent_path() / p).lexically_normal().string();
}

}  // namespace f2::lsp
