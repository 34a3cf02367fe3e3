#pragma once
/// SPEC 7's limits that more than the parser enforces: the one place they are
/// written. The parser's ParseLimits start from them; the command line's
/// --size and the viewer's render size check against them too.
#include <cstdint>

namespace f2 {

inline constexpr int kMaxImageSide = 16384;
inline constexpr std::int64_t kMaxImagePixels = std::int64_t{1} << 26;
inline constexpr int kMaxKeyFrame = 10'000'000;

/// A `width` x `height` image is within the limits (and not empty).
inline bool imageSizeAllowed(int width, int height) {
    return width >= 1 && height >= 1 && width <= kMaxImageSide && height <= kMaxImageSide &&
           std::int64_t(width) * height <= kMaxImagePixels;
}

}  // namespace f2
