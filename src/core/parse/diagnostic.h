#pragma once
/// Errors and warnings with a place in the source, printed like a compiler's.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace f2 {

struct SourceLoc {
    std::string file;
    int line = 0;    ///< 1-based
    int column = 0;  ///< 1-based, in bytes
};

enum class Severity { Error, Warning };

struct Diagnostic {
    SourceLoc loc;
    Severity severity = Severity::Error;
    std::string message;
    /// Bytes of the line the problem covers from loc.column, as written (a
    /// whole `( … )` argument, spaces and all); 0 when it is a point (where a
    /// missing argument would go) or the parser knows no extent.
    int length = 0;

    /// `FILE:LINE:COL: error: message` (or `warning:`).
    std::string format() const;
};

bool hasErrors(const std::vector<Diagnostic>& diagnostics);

/// Bytes of a line, 0-based.
struct ByteSpan {
    std::size_t first = 0;
    std::size_t length = 0;
};

/// The bytes of `lineText` (the diagnostic's line, without its line end) that
/// an editor marks for `d`: its `length` from its column; without one, the
/// token that starts there (to a space, tab or '#'); at the end of the line,
/// its last byte. The one rule for the viewer's underline and the language
/// server's range. Empty only for an empty line.
ByteSpan markedBytes(const Diagnostic& d, std::string_view lineText);

}  // namespace f2
