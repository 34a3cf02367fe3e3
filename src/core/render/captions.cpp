#include "core/render/captions.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/parse/lexer.h"
#include "core/render/caption_font.h"

// The implementation, private to this file; a system header, so its own code
// is not held to the project's warnings.
#define STBTT_STATIC
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb/stb_truetype.h>

namespace f2 {

namespace {

/// The caption font, read once (stb_truetype reads the bytes in place).
const stbtt_fontinfo& font() {
    static const stbtt_fontinfo info = [] {
        stbtt_fontinfo f{};
        const std::span<const unsigned char> bytes = captionFont();
        stbtt_InitFont(&f, bytes.data(), stbtt_GetFontOffsetForIndex(bytes.data(), 0));
        return f;
    }();
    return info;
}

/// `ink` over `pixel` at `coverage` (0..255), rounded to the nearest byte.
void blend(Rgb8& pixel, Rgb8 ink, unsigned coverage) {
    auto mix = [coverage](std::uint8_t under, std::uint8_t over) {
        return std::uint8_t((unsigned(under) * (255u - coverage) + unsigned(over) * coverage + 127u) / 255u);
    };
    pixel = {mix(pixel.r, ink.r), mix(pixel.g, ink.g), mix(pixel.b, ink.b)};
}

/// Rasterizes `glyph` whose bitmap box, at this scale and sub-pixel shift, has
/// its top left at (left, top) of the image, and blends the part of it inside
/// the image. Only that part is rasterized: a glyph larger than the picture
/// costs no more than the picture.
void drawGlyph(Image& image, int glyph, float scale, float shiftX, float shiftY, int penX, int baseY,
               Rgb8 ink, std::vector<unsigned char>& coverage) {
    const stbtt_fontinfo& f = font();
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetGlyphBitmapBoxSubpixel(&f, glyph, scale, scale, shiftX, shiftY, &x0, &y0, &x1, &y1);
    // The box in image pixels, clipped to the image.
    const int left = std::max(penX + x0, 0), right = std::min(penX + x1, image.width);
    const int top = std::max(baseY + y0, 0), bottom = std::min(baseY + y1, image.height);
    if (left >= right || top >= bottom) return;
    stbtt_vertex* vertices = nullptr;
    const int count = stbtt_GetGlyphShape(&f, glyph, &vertices);
    if (count > 0) {
        stbtt__bitmap window;
        window.w = right - left;
        window.h = bottom - top;
        window.stride = window.w;
        coverage.assign(std::size_t(window.w) * std::size_t(window.h), 0);
        window.pixels = coverage.data();
        // The window's offset in the glyph's own pixel grid (stb's x_off, y_off).
        stbtt_Rasterize(&window, 0.35f, vertices, count, scale, scale, shiftX, shiftY, left - penX,
                        top - baseY, 1, nullptr);
        for (int y = 0; y < window.h; ++y) {
            for (int x = 0; x < window.w; ++x) {
                const unsigned c = coverage[std::size_t(y) * std::size_t(window.w) + std::size_t(x)];
                if (c > 0) blend(image.at(left + x, top + y), ink, c);
            }
        }
    }
    stbtt_FreeShape(&f, vertices);
}

}  // namespace

void drawCaption(Image& image, const Caption& caption) {
    if (image.width <= 0 || image.height <= 0 || caption.text.empty()) return;
    const stbtt_fontinfo& f = font();
    const float scale = stbtt_ScaleForMappingEmToPixels(&f, caption.size * float(image.height));
    const Rgb8 ink{caption.colour.r, caption.colour.g, caption.colour.b};
    // The pen moves in fractional pixels; each glyph is rasterized at its
    // own sub-pixel shift, so spacing does not depend on rounding.
    float pen = caption.x * float(image.width);
    const float baseline = caption.y * float(image.height);
    const int baseY = int(std::floor(baseline));
    const float shiftY = baseline - float(baseY);
    std::vector<unsigned char> coverage;
    int previous = 0;
    for (std::size_t i = 0; i < caption.text.size();) {
        const Utf8Char c = decodeUtf8(caption.text, i);
        i += std::max<std::size_t>(c.bytes, 1);                   // the parser gives valid UTF-8
        const int glyph = stbtt_FindGlyphIndex(&f, int(c.code));  // 0: the font's "missing" box
        if (previous != 0) pen += scale * float(stbtt_GetGlyphKernAdvance(&f, previous, glyph));
        if (pen >= float(image.width)) break;  // left to right: the rest is off the picture
        const int penX = int(std::floor(pen));
        drawGlyph(image, glyph, scale, pen - float(penX), shiftY, penX, baseY, ink, coverage);
        int advance = 0, bearing = 0;
        stbtt_GetGlyphHMetrics(&f, glyph, &advance, &bearing);
        pen += scale * float(advance);
        previous = glyph;
    }
}

void drawCaptions(Image& image, std::span<const Caption> captions, double t) {
    for (const Caption& caption : captions) {
        if (caption.shownAt(t)) drawCaption(image, caption);
    }
}

}  // namespace f2
