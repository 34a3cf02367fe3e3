#include "core/render/view_legend.h"

#include <cmath>
#include <string>

#include "core/render/shading.h"

namespace f2 {

namespace {
/// Digits 0-9 in a 3 x 5 pixel font, one row of three bits (left = 4) per entry.
constexpr unsigned char kDigits[10][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
    {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7},
};
constexpr int kScale = 2;             // font pixels per digit pixel
constexpr int kAdvance = 4 * kScale;  // digit width plus one column of space
constexpr int kPad = 4;               // panel edge to its content
constexpr int kBarWidth = kLegendWidth - 2 * kPad, kBarHeight = 8;
constexpr Rgb8 kPanel{24, 24, 24}, kInk{255, 255, 255};

void fill(Image& image, int x0, int y0, int w, int h, Rgb8 colour) {
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) image.at(x, y) = colour;
}

void drawNumber(Image& image, int x, int y, const std::string& digits) {
    for (char c : digits) {
        for (int row = 0; row < 5; ++row)
            for (int col = 0; col < 3; ++col)
                if (kDigits[c - '0'][row] & (4 >> col))
                    fill(image, x + col * kScale, y + row * kScale, kScale, kScale, kInk);
        x += kAdvance;
    }
}

int textWidth(const std::string& digits) { return int(digits.size()) * kAdvance - kScale; }
}  // namespace

bool drawViewLegend(Image& image, ViewMode mode, const ViewRange& range) {
    if (mode != ViewMode::Depth && mode != ViewMode::Cost) return false;
    if (image.width < kLegendWidth + 2 * kLegendMargin || image.height < kLegendHeight + 2 * kLegendMargin)
        return false;
    const int x0 = kLegendMargin, y0 = image.height - kLegendMargin - kLegendHeight;
    fill(image, x0, y0, kLegendWidth, kLegendHeight, kPanel);

    // The bar, framed in white so its dark end shows against the panel.
    const int bx = x0 + kPad, by = y0 + kPad;
    fill(image, bx - 1, by - 1, kBarWidth + 2, kBarHeight + 2, kInk);
    for (int i = 0; i < kBarWidth; ++i) {
        const float v = (float(i) + 0.5f) / float(kBarWidth);
        // Cost: the heat ramp; depth: its greys from white (near) to 0.1 (far).
        const Vec3 c = mode == ViewMode::Cost ? heatRamp(v) : Vec3{1, 1, 1} * (1.0f - 0.9f * v);
        fill(image, bx + i, by, 1, kBarHeight, {toByte(c.x), toByte(c.y), toByte(c.z)});
    }

    // The values at the ends: cost from 0 to its largest, depth nearest to farthest.
    const float low = mode == ViewMode::Cost ? 0.0f : range.low;
    const std::string left = std::to_string(std::lround(low)),
                      right = std::to_string(std::lround(range.high));
    const int ty = by + kBarHeight + 3;
    drawNumber(image, bx, ty, left);
    drawNumber(image, bx + kBarWidth - textWidth(right), ty, right);
    return true;
}

}  // namespace f2
