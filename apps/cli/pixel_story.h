#pragma once
/// `f2 render --pixel X,Y`: prints the core's PixelReport of one pixel.
#include <string>

#include "core/render/camera.h"
#include "scene_source.h"

namespace f2::cli {

/// Parses "X,Y" as a pixel of a width x height image; false with a message.
bool parsePixel(const std::string& text, int width, int height, int& x, int& y, std::string& error);

/// Renders frame `t` (to show what the image holds at the pixel) and prints
/// the story of pixel (x, y) on standard output. Returns the exit code.
int printPixelStory(const LoadedScene& loaded, const Camera& camera, double t, int x, int y, int antialias,
                    int threads);

}  // namespace f2::cli
