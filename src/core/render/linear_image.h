#pragma once
/// An RGB image of float colours (0..1, the shaded values before the 8-bit
/// conversion), rows top to bottom: where several images are averaged (motion
/// blur) so that rounding happens once, at the end.
#include <cstddef>
#include <vector>

namespace f2 {

struct LinearRgb {
    float r = 0, g = 0, b = 0;
};

struct LinearImage {
    int width = 0, height = 0;
    std::vector<LinearRgb> pixels;

    void resize(int w, int h) {
        width = w;
        height = h;
        pixels.resize(std::size_t(w) * std::size_t(h));
    }
    LinearRgb& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

}  // namespace f2
