// image_compare — PNG comparisons for the output tests (reads with f2::io).
//   image_compare iou A.png B.png R G B MIN      foreground (pixel != background
//       R G B) masks of A and B: intersection over union must be >= MIN
//   image_compare aa PLAIN.png AA.png           AA differs from PLAIN somewhere,
//       and only on edges (a step to a neighbour in either image)
//   image_compare match A.png B.png R G B TOL MAXOFF   the same coverage (pixel !=
//       background R G B in both or in neither, everywhere), and at most MAXOFF
//       pixels differ by more than TOL in a channel
//   image_compare mean A.png B.png R G B MAX     the same coverage, and the mean
//       absolute difference over every channel of every pixel at most MAX levels
//   image_compare diff A.png B.png              statistics only (exit 0 if same size)
//   image_compare same A.png B.png              every pixel identical (exit 1 otherwise)
//   image_compare colours A.png MIN             A has at least MIN distinct colours
//       (a rendered scene, not a blank or flat image)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "io/png_writer.h"

namespace {
using f2::Image;
using f2::Rgb8;

int channelDiff(Rgb8 a, Rgb8 b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

bool load(const char* path, Image& image) {
    std::string error;
    if (f2::readPng(path, image, error)) return true;
    std::fprintf(stderr, "image_compare: %s\n", error.c_str());
    return false;
}

int iou(const Image& a, const Image& b, Rgb8 bg, double minimum) {
    long both = 0, either = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        bool fa = !(a.pixels[i] == bg), fb = !(b.pixels[i] == bg);
        both += fa && fb;
        either += fa || fb;
    }
    double value = either ? double(both) / double(either) : 1.0;
    std::printf("foreground IoU %.5f (%ld both, %ld either, %zu pixels)\n", value, both, either,
                a.pixels.size());
    // An all-background pair would pass vacuously: that is a broken test, not a match.
    if (either == 0) return std::puts("FAIL: no foreground at all"), 1;
    if (value < minimum) return std::printf("FAIL: IoU below %.4f\n", minimum), 1;
    return 0;
}

/// Largest step from pixel (x, y) to one of its 8 neighbours.
int neighbourJump(const Image& image, int x, int y) {
    int jump = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            int nx = std::clamp(x + dx, 0, image.width - 1), ny = std::clamp(y + dy, 0, image.height - 1);
            jump = std::max(jump, channelDiff(image.at(x, y), image.at(nx, ny)));
        }
    return jump;
}

/// Supersampling may only change pixels on an edge: where either image steps
/// to a neighbour (the AA image too, for features thinner than a pixel that
/// the centre ray missed). A flat or smoothly shaded area must stay as it was.
int antialias(const Image& plain, const Image& aa) {
    constexpr int kSame = 2, kEdge = 6;  // byte steps: rounding noise vs a discontinuity
    long differing = 0, offEdge = 0;
    for (int y = 0; y < plain.height; ++y)
        for (int x = 0; x < plain.width; ++x) {
            int d = channelDiff(plain.at(x, y), aa.at(x, y));
            if (d <= kSame) continue;
            ++differing;
            if (neighbourJump(plain, x, y) < kEdge && neighbourJump(aa, x, y) < kEdge && offEdge++ < 5)
                std::printf("  differs by %d away from any edge at (%d, %d)\n", d, x, y);
        }
    long pixels = long(plain.pixels.size());
    std::printf("%ld of %ld pixels differ (> %d), %ld of them away from edges\n", differing, pixels, kSame,
                offEdge);
    if (differing == 0) return std::puts("FAIL: anti-aliasing changed nothing"), 1;
    if (offEdge > 0) return std::puts("FAIL: anti-aliasing changed pixels away from edges"), 1;
    if (differing * 5 > pixels) return std::puts("FAIL: anti-aliasing changed over a fifth of the image"), 1;
    return 0;
}

int match(const Image& a, const Image& b, Rgb8 bg, int tolerance, long maxOff) {
    long coverage = 0, off = 0, foreground = 0;
    int maximum = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        bool fa = !(a.pixels[i] == bg), fb = !(b.pixels[i] == bg);
        foreground += fa;
        if (fa != fb && coverage++ < 5)
            std::printf("  coverage differs at (%zu, %zu)\n", i % std::size_t(a.width),
                        i / std::size_t(a.width));
        int d = channelDiff(a.pixels[i], b.pixels[i]);
        off += d > tolerance;
        maximum = std::max(maximum, d);
    }
    std::printf("%ld foreground pixels; coverage differs in %ld; %ld differ by more than %d (max %d)\n",
                foreground, coverage, off, tolerance, maximum);
    if (foreground == 0) return std::puts("FAIL: no foreground at all"), 1;
    if (coverage > 0) return std::puts("FAIL: the images cover different pixels"), 1;
    if (off > maxOff) return std::printf("FAIL: more than %ld pixels beyond the tolerance\n", maxOff), 1;
    return 0;
}

int meanDifference(const Image& a, const Image& b, Rgb8 bg, double maximum) {
    long coverage = 0;
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        coverage += !(a.pixels[i] == bg) != !(b.pixels[i] == bg);
        Rgb8 p = a.pixels[i], q = b.pixels[i];
        sum += std::abs(p.r - q.r) + std::abs(p.g - q.g) + std::abs(p.b - q.b);
    }
    double mean = sum / (3.0 * double(a.pixels.size()));
    std::printf("coverage differs in %ld pixels; mean absolute difference %.4f levels (bound %.4f)\n",
                coverage, mean, maximum);
    if (coverage > 0) return std::puts("FAIL: the images cover different pixels"), 1;
    if (mean > maximum) return std::puts("FAIL: the mean difference is above the bound"), 1;
    return 0;
}

int diff(const Image& a, const Image& b) {
    long differing = 0, over8 = 0, sum = 0;
    int maximum = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        int d = channelDiff(a.pixels[i], b.pixels[i]);
        differing += d > 0;
        over8 += d > 8;
        sum += d;
        maximum = std::max(maximum, d);
    }
    std::printf("%ld of %zu pixels differ, %ld by more than 8, max %d, mean %.4f\n", differing,
                a.pixels.size(), over8, maximum, double(sum) / double(a.pixels.size()));
    return 0;
}
/// Pixel-exact equality: the decoded bytes, not the PNG files, whose
/// compression may differ between zlib versions.
int same(const Image& a, const Image& b) {
    long differing = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            Rgb8 p = a.at(x, y), q = b.at(x, y);
            if (p == q) continue;
            if (differing++ < 5)
                std::printf("  (%d, %d): %d %d %d vs %d %d %d\n", x, y, p.r, p.g, p.b, q.r, q.g, q.b);
        }
    std::printf("%ld of %zu pixels differ\n", differing, a.pixels.size());
    return differing == 0 ? 0 : 1;
}

int colours(const Image& a, long minimum) {
    std::set<std::uint32_t> seen;
    for (Rgb8 p : a.pixels) seen.insert(std::uint32_t(p.r) << 16 | std::uint32_t(p.g) << 8 | p.b);
    std::printf("%zu distinct colours (need %ld)\n", seen.size(), minimum);
    return long(seen.size()) >= minimum ? 0 : 1;
}
}  // namespace

int main(int argc, char** argv) {
    std::string mode = argc > 1 ? argv[1] : "";
    bool known = ((mode == "iou" || mode == "mean") && argc == 8) || (mode == "match" && argc == 9) ||
                 ((mode == "aa" || mode == "diff" || mode == "same") && argc == 4) ||
                 (mode == "colours" && argc == 4);
    if (!known) {
        std::fprintf(
            stderr,
            "usage: image_compare iou A B R G B MIN | match A B R G B TOL MAXOFF | mean A B R G B MAX | "
            "aa PLAIN AA | diff A B | "
            "same A B | colours A MIN\n");
        return 2;
    }
    if (mode == "colours") {
        Image a;
        return load(argv[2], a) ? colours(a, std::atol(argv[3])) : 1;
    }
    Image a, b;
    if (!load(argv[2], a) || !load(argv[3], b)) return 1;
    if (a.width != b.width || a.height != b.height) {
        std::printf("FAIL: sizes differ: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
        return 1;
    }
    if (mode == "iou" || mode == "match" || mode == "mean") {
        Rgb8 bg{std::uint8_t(std::atoi(argv[4])), std::uint8_t(std::atoi(argv[5])),
                std::uint8_t(std::atoi(argv[6]))};
        if (mode == "mean") return meanDifference(a, b, bg, std::atof(argv[7]));
        return mode == "iou" ? iou(a, b, bg, std::atof(argv[7]))
                             : match(a, b, bg, std::atoi(argv[7]), std::atol(argv[8]));
    }
    if (mode == "same") return same(a, b);
    return mode == "aa" ? antialias(a, b) : diff(a, b);
}
