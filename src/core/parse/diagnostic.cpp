#include "core/parse/diagnostic.h"

#include <algorithm>

namespace f2 {

std::string Diagnostic::format() const {
    std::string out = loc.file;
    out += ':';
    out += std::to_string(loc.line);
    out += ':';
    out += std::to_string(loc.column);
    out += severity == Severity::Error ? ": error: " : ": warning: ";
    out += message;
    return out;
}

ByteSpan markedBytes(const Diagnostic& d, std::string_view lineText) {
    if (lineText.empty()) return {};
    const std::size_t first =
        std::min(static_cast<std::size_t>(std::max(d.loc.column, 1) - 1), lineText.size());
    if (first == lineText.size()) return {first - 1, 1};  // a missing argument: mark the line's end
    if (d.length > 0) return {first, std::min(static_cast<std::size_t>(d.length), lineText.size() - first)};
    std::size_t end = first;
    while (end < lineText.size() && lineText[end] != ' ' && lineText[end] != '\t' && lineText[end] != '#')
        ++end;
    return {first, std::max<std::size_t>(end - first, 1)};
}

bool hasErrors(const std::vector<Diagnostic>& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

}  // namespace f2
