#pragma once
/// A text in double quotes, as `/caption` takes it (SPEC 10.5): `"…"` with
/// `\"` for a quote and `\\` for a backslash inside.
#include <cstddef>
#include <string>
#include <string_view>

namespace f2 {

struct QuotedText {
    bool ok = false;
    std::string text;        ///< the text between the quotes, escapes undone
    std::string message;     ///< what is wrong, when not ok
    std::size_t offset = 0;  ///< where in the token it is wrong (bytes)
};

/// Reads `token`, which must be a whole quoted text: one opening quote, the
/// closing one at its end, valid UTF-8 between. A backslash before any other
/// character stays as written (`"C:\scenes"`).
QuotedText readQuotedText(std::string_view token);

}  // namespace f2
