#pragma once
/// Numbered output file names such as `frames/f_%04d.png`: one printf-style
/// integer conversion, `%d` or zero-padded `%0Nd` (`%4d` is refused: spaces in
/// file names), `%%` for a literal percent sign.
/// Parsed here rather than handed to printf, so a user's path can never be a
/// format-string hole.
#include <cstdint>
#include <optional>
#include <string>

namespace f2 {

struct FramePattern {
    std::string prefix, suffix;  ///< text around the conversion, `%%` already undone
    int width = 0;               ///< minimum digits, zero-padded (0 = as many as needed)
    bool zeroPad = false;        ///< always true when width > 0

    /// The file name of frame `frame` (>= 0).
    std::string format(std::int64_t frame) const;
};

/// True if `path` contains a `%` that is not `%%`: the user meant a pattern.
bool looksLikeFramePattern(const std::string& path);

/// Parses `path`; nullopt with `error` set unless it has exactly one integer
/// conversion and no other `%` than `%%`.
std::optional<FramePattern> parseFramePattern(const std::string& path, std::string& error);

}  // namespace f2
