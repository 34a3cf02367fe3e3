#pragma once
/// Errors and warnings with a place in the source, printed like a compiler's.
#include <string>
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

    /// `FILE:LINE:COL: error: message` (or `warning:`).
    std::string format() const;
};

bool hasErrors(const std::vector<Diagnostic>& diagnostics);

}  // namespace f2
