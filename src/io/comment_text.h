#pragma once

#include <string>
#include <string_view>

namespace f2 {

/// `text` made safe to stand inside a one-line comment of an exported file
/// (POV-Ray's `//`, the primitive list's `#`): a scene's path or a name is
/// outside the scene's numbers and may hold anything, so every control byte
/// (a newline would end the comment and make the rest live SDL) is written as
/// a visible escape (`\n`, `\r`, `\t`, `\xNN`), and a backslash as `\\` so the
/// escapes stay unambiguous. Printable bytes, UTF-8 included, pass unchanged.
std::string commentText(std::string_view text);

}  // namespace f2
