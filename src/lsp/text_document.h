#pragma once
/// An open document's text with its lines, and the conversion between the
/// parser's places (1-based line, 1-based byte column) and LSP positions
/// (0-based line, 0-based column in UTF-16 code units).
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace f2::lsp {

/// An LSP position: 0-based line, 0-based character in UTF-16 code units.
struct Position {
    int line = 0;
    int character = 0;
    friend bool operator==(const Position&, const Position&) = default;
};

struct Range {
    Position start;
    Position end;
    friend bool operator==(const Range&, const Range&) = default;
};

/// UTF-16 code units of `bytes` read as UTF-8 (an invalid byte counts as one
/// unit, as an editor shows it as U+FFFD).
int utf16Length(std::string_view bytes);

/// Byte offset in `line` of UTF-16 column `character`, clamped to the line
/// (a column inside a surrogate pair or beyond the end gives the nearest end).
std::size_t byteOffsetOfUtf16(std::string_view line, int character);

class TextDocument {
   public:
    TextDocument() = default;
    TextDocument(std::string text, int version);

    const std::string& text() const { return text_; }
    int version() const { return version_; }
    int lineCount() const { return static_cast<int>(lines_.size()); }
    /// Line `index` (0-based) without its line end; empty when out of range.
    std::string_view line(int index) const;

    /// The LSP position of a parser place (1-based line and byte column, the
    /// column counted after a byte order mark on line 1). Clamped to the text.
    Position position(int line, int byteColumn) const;
    /// The range of the token that starts at a parser place: up to the next
    /// space, tab or '#' (or the end of the line). A place past the end of its
    /// line gives an empty range there.
    Range tokenRange(int line, int byteColumn) const;
    /// The range of `length` bytes from a parser place.
    Range range(int line, int byteColumn, int length) const;
    /// The whole of line `index` (0-based).
    Range lineRange(int index) const;

    /// Byte offset in line(position.line) of an LSP position, or -1 when the
    /// line does not exist.
    long byteInLine(const Position& p) const;

   private:
    /// Byte offset in line(index) of a 1-based parser column.
    std::size_t byteOfColumn(int index, int byteColumn) const;

    std::string text_;
    int version_ = 0;
    /// Start and length in text_ of each line (offsets, not views, so that a
    /// copied or moved document stays valid).
    std::vector<std::pair<std::size_t, std::size_t>> lines_;
    bool bom_ = false;
};

}  // namespace f2::lsp
