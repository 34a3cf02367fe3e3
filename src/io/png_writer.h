#pragma once
/// PNG output through libpng, written atomically.
#include <cstdio>
#include <string>

#include "core/render/image.h"

namespace f2 {

/// Writes `image` to `path` (temporary file, then rename). On failure returns
/// false, sets `error` and leaves no file behind.
bool writePng(const Image& image, const std::string& path, std::string& error);

/// Writes `image` as PNG to an open stream (standard output for `-o -`).
/// False with `error` set if the stream fails.
bool writePng(const Image& image, std::FILE* stream, std::string& error);

/// Reads an 8-bit RGB or RGBA PNG (tests, comparisons). False on failure.
bool readPng(const std::string& path, Image& image, std::string& error);

}  // namespace f2
