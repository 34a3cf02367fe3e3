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

std::vector<VariableOccurrence> scanVariables(const TextDocument& doc) {
    std::vector<VariableOccurrence> out;
    for (int index = 0; index < doc.lineCount(); ++index) {
        const std::string_view code = withoutComment(doc.line(index));
        std::size_t wordEnd = 0;
        const std::string_view command = firstWord(code, wordEnd);
        if (command == "/include") continue;
        std::size_t i = 0;
        if (command == "/let" || command == "/repeat") {
            std::size_t b = code.find_first_not_of(" \t", wordEnd);
            if (b != std::string_view::npos && isNameStart(code[b])) {
                std::size_t e = b;
                while (e < code.size() && isNameChar(code[e])) ++e;
                out.push_back({std::string(code.substr(b, e - b)), index, b, e, true, command == "/repeat", 0,
                               static_cast<std::uint32_t>(index)});
                i = e;
            }
        }
        int depth = 0;
        while (i < code.size()) {
            const char c = code[i];
            if (c == '(' || c == '{') ++depth;
            if ((c == ')' || c == '}') && depth > 0) --depth;
            if (depth > 0 && isNameStart(c) && (i == 0 || !isNameChar(code[i - 1]))) {
                std::size_t e = i;
                while (e < code.size() && isNameChar(code[e])) ++e;
                const std::string_view name = code.substr(i, e - i);
                std::size_t next = e;
                while (next < code.size() && (code[next] == ' ' || code[next] == '\t')) ++next;
                const bool call = next < code.size() && code[next] == '(';
                // Numbers such as 1e3 start with a digit, so a name here is a variable or a function.
                const bool isNumberExponent = i > 0 && (code[i - 1] >= '0' && code[i - 1] <= '9');
                if (!call && name != "pi" && !isNumberExponent) {
                    out.push_back(
                        {std::string(name), index, i, e, false, false, 0, static_cast<std::uint32_t>(index)});
                }
                i = e;
                continue;
            }
            ++i;
        }
    }
    return out;
}

std::optional<VariableOccurrence> definitionOf(const std::vector<VariableOccurrence>& all,
                                               std::string_view name, std::uint32_t order) {
    std::optional<VariableOccurrence> first, nearest;
    for (const VariableOccurrence& o : all) {
        if (!o.definition || o.name != name) continue;
        if (!first) first = o;
        if (o.order <= order) nearest = o;
    }
    return nearest ? nearest : first;
}

std::optional<IncludePath> includeOn(const TextDocument& doc, int line) {
    const std::string_view text = doc.line(line);
    const std::string_view code = withoutComment(text);
    std::size_t wordEnd = 0;
    if (firstWord(code, wordEnd) != "/include") return std::nullopt;
    const std::size_t b = code.find_first_not_of(" \t", wordEnd);
    if (b == std::string_view::npos) return std::nullopt;
    if (code[b] == '"') {
        const std::size_t close = code.find('"', b + 1);
        const std::size_t e = close == std::string_view::npos ? code.size() : close + 1;
        const std::size_t innerEnd = close == std::string_view::npos ? code.size() : close;
        return IncludePath{std::string(code.substr(b + 1, innerEnd - b - 1)), b, e};
    }
    std::size_t e = b;
    while (e < code.size() && code[e] != ' ' && code[e] != '\t') ++e;
    return IncludePath{std::string(code.substr(b, e - b)), b, e};
}

std::string resolveInclude(std::string_view documentPath, std::string_view path) {
    namespace fs = std::filesystem;
    const fs::path p{std::string(path)};
    if (p.is_absolute()) return p.lexically_normal().string();
    return (fs::path(std::string(documentPath)).parent_path() / p).lexically_normal().string();
}

}  // namespace f2::lsp
