#include "lsp/text_document.h"

#include <algorithm>
#include <cstdint>

namespace f2::lsp {

namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

/// Length of the UTF-8 sequence that byte `b` starts (1 for an invalid byte).
std::size_t sequenceLength(std::string_view s, std::size_t i) {
    const auto b = static_cast<std::uint8_t>(s[i]);
    std::size_t len = 1;
    if ((b & 0xE0) == 0xC0)
        len = 2;
    else if ((b & 0xF0) == 0xE0)
        len = 3;
    else if ((b & 0xF8) == 0xF0)
        len = 4;
    if (len == 1 || i + len > s.size()) return 1;
    for (std::size_t k = 1; k < len; ++k) {
        if ((static_cast<std::uint8_t>(s[i + k]) & 0xC0) != 0x80) return 1;
    }
    return len;
}

bool endsToken(char c) { return c == ' ' || c == '\t' || c == '#'; }

}  // namespace

int utf16Length(std::string_view bytes) {
    int units = 0;
    for (std::size_t i = 0; i < bytes.size();) {
        const std::size_t len = sequenceLength(bytes, i);
        units += len == 4 ? 2 : 1;  // code points above U+FFFF take a surrogate pair
        i += len;
    }
    return units;
}

std::size_t byteOffsetOfUtf16(std::string_view line, int character) {
    int units = 0;
    std::size_t i = 0;
    while (i < line.size()) {
        const std::size_t len = sequenceLength(line, i);
        const int width = len == 4 ? 2 : 1;
        if (units + width > character) break;
        units += width;
        i += len;
    }
    return i;
}

TextDocument::TextDocument(std::string text, int version) : text_(std::move(text)), version_(version) {
    // Lines as the parser counts them: "\n" or "\r\n" ends a line. A client
    // counts a lone "\r" as a line end too, but the scene language does not.
    std::size_t start = 0;
    for (;;) {
        const std::size_t nl = text_.find('\n', start);
        std::size_t end = nl == std::string::npos ? text_.size() : nl;
        if (end > start && text_[end - 1] == '\r') --end;
        lines_.emplace_back(start, end - start);
        if (nl == std::string::npos) break;
        start = nl + 1;
    }
    bom_ = text_.starts_with(kUtf8Bom);
}

std::string_view TextDocument::line(int index) const {
    if (index < 0 || index >= lineCount()) return {};
    const auto [start, length] = lines_[static_cast<std::size_t>(index)];
    return std::string_view(text_).substr(start, length);
}

std::size_t TextDocument::byteOfColumn(int index, int byteColumn) const {
    const std::size_t skipped = index == 0 && bom_ ? kUtf8Bom.size() : 0;
    const long byte = static_cast<long>(skipped) + std::max(byteColumn, 1) - 1;
    return std::min(static_cast<std::size_t>(byte), line(index).size());
}

Position TextDocument::position(int line, int byteColumn) const {
    if (lines_.empty()) return {};
    const int index = std::clamp(line - 1, 0, lineCount() - 1);
    const std::string_view text = this->line(index);
    return {index, utf16Length(text.substr(0, byteOfColumn(index, byteColumn)))};
}

Range TextDocument::tokenRange(int line, int byteColumn) const {
    const Position start = position(line, byteColumn);
    const std::string_view text = this->line(start.line);
    std::size_t b = byteOfColumn(start.line, byteColumn);
    const std::size_t first = b;
    while (b < text.size() && !endsToken(text[b])) ++b;
    return {start, {start.line, start.character + utf16Length(text.substr(first, b - first))}};
}

Range TextDocument::range(int line, int byteColumn, int length) const {
    const Position start = position(line, byteColumn);
    const std::string_view text = this->line(start.line);
    const std::size_t first = byteOfColumn(start.line, byteColumn);
    const std::size_t last = std::min(text.size(), first + static_cast<std::size_t>(std::max(length, 0)));
    return {start, {start.line, start.character + utf16Length(text.substr(first, last - first))}};
}

Range TextDocument::lineRange(int index) const { return {{index, 0}, {index, utf16Length(line(index))}}; }

long TextDocument::byteInLine(const Position& p) const {
    if (p.line < 0 || p.line >= lineCount() || p.character < 0) return -1;
    return static_cast<long>(byteOffsetOfUtf16(line(p.line), p.character));
}

}  // namespace f2::lsp
