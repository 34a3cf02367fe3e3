#pragma once
/// An 8-bit RGB image, rows top to bottom.
#include <cstdint>
#include <vector>

namespace f2 {

struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

struct Image {
    int width = 0, height = 0;
    std::vector<Rgb8> pixels;

    void resize(int w, int h) {
        width = w;
        height = h;
        pixels.resize(std::size_t(w) * std::size_t(h));
    }
    Rgb8& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const Rgb8& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    friend bool operator==(const Image&, const Image&) = default;
};

}  // namespace f2
