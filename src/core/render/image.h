#pragma once
/// An 8-bit RGB image, rows top to bottom.
#include <cstdint>
#include <vector>

namespace f2 {

struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

/// A width x height grid of pixels, rows top to bottom.
template <class Pixel>
struct PixelGrid {
    int width = 0, height = 0;
    std::vector<Pixel> pixels;

    void resize(int w, int h) {
        width = w;
        height = h;
        pixels.resize(std::size_t(w) * std::size_t(h));
    }
    Pixel& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const Pixel& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    friend bool operator==(const PixelGrid&, const PixelGrid&) = default;
};

using Image = PixelGrid<Rgb8>;

}  // namespace f2
