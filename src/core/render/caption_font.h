#pragma once
/// The font of `/caption` (SPEC 10.5), compiled into the core so that every
/// build draws the same pixels with no file to find: DejaVu Sans Bold
/// (src/core/render/font/, its licence beside it), embedded by
/// cmake/EmbedFile.cmake.
#include <span>

namespace f2 {

/// The TrueType file's bytes.
std::span<const unsigned char> captionFont();

}  // namespace f2
