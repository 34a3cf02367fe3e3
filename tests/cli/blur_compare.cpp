// blur_compare — checks f2's motion blur against sub-frames rendered elsewhere
// (POV-Ray, from `f2 export --pov` at each sub-frame's time):
//   blur_compare BLURRED.png SHARP.png BOUND MEAN_OUT.png SUB1.png ... SUBn.png
// averages the sub-frames per channel (rounded as f2 rounds: floor(x + 0.5)),
// writes that mean to MEAN_OUT.png (for a side-by-side picture), and requires
// the mean absolute difference between BLURRED (f2 --motion-blur) and it to be
// at most BOUND levels, and f2's sharp frame at the same time (SHARP) to be at
// least three times as far from it: a test that also passes without blur
// would prove nothing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/png_writer.h"

namespace {
using f2::Image;

bool load(const char* path, Image& image) {
    std::string error;
    if (f2::readPng(path, image, error)) return true;
    std::fprintf(stderr, "blur_compare: %s\n", error.c_str());
    return false;
}

int channelSum(f2::Rgb8 a, f2::Rgb8 b) {
    return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

/// Mean absolute difference over every channel of the pixels where `in` is
/// true (all when empty), in levels.
double meanDifference(const Image& a, const Image& b, const std::vector<bool>& in = {}) {
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        if (!in.empty() && !in[i]) continue;
        sum += channelSum(a.pixels[i], b.pixels[i]);
        ++count;
    }
    return count ? sum / (3.0 * double(count)) : 0;
}

/// Per channel, the mean of the images, rounded to the nearest level.
Image average(const std::vector<Image>& images) {
    Image mean;
    mean.resize(images.front().width, images.front().height);
    const double n = double(images.size());
    auto level = [n](double sum) { return std::uint8_t(std::floor(sum / n + 0.5)); };
    for (std::size_t i = 0; i < mean.pixels.size(); ++i) {
        double r = 0, g = 0, b = 0;
        for (const Image& image : images) {
            r += image.pixels[i].r;
            g += image.pixels[i].g;
            b += image.pixels[i].b;
        }
        mean.pixels[i] = {level(r), level(g), level(b)};
    }
    return mean;
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 6) {
        std::fprintf(stderr, "usage: blur_compare BLURRED.png SHARP.png BOUND MEAN_OUT.png SUB1.png ...\n");
        return 2;
    }
    Image blurred, sharp;
    if (!load(argv[1], blurred) || !load(argv[2], sharp)) return 1;
    const double bound = std::atof(argv[3]);
    std::vector<Image> subs(std::size_t(argc - 5));
    for (int i = 5; i < argc; ++i) {
        Image& sub = subs[std::size_t(i - 5)];
        if (!load(argv[i], sub)) return 1;
        if (sub.width != blurred.width || sub.height != blurred.height || sharp.width != blurred.width ||
            sharp.height != blurred.height)
            return std::printf("FAIL: sizes differ (%s)\n", argv[i]), 1;
    }
    const Image mean = average(subs);
    std::string error;
    if (!f2::writePng(mean, argv[4], error)) return std::printf("FAIL: %s\n", error.c_str()), 1;

    const double blurredOff = meanDifference(blurred, mean), sharpOff = meanDifference(sharp, mean);
    std::printf(
        "mean of %zu sub-frames vs f2's motion blur: mean absolute difference %.4f levels (bound %.4f); "
        "vs f2's sharp frame %.4f\n",
        subs.size(), blurredOff, bound, sharpOff);
    // The same over the pixels that motion changes (the sharp frame differs there by more than 2 levels
    // in a channel), where the whole image's mean would hide a difference among static pixels.
    std::vector<bool> moving(mean.pixels.size());
    std::size_t movingCount = 0;
    for (std::size_t i = 0; i < moving.size(); ++i) {
        const f2::Rgb8 p = sharp.pixels[i], q = mean.pixels[i];
        moving[i] = std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)}) > 2;
        movingCount += moving[i];
    }
    std::printf(
        "over the %zu pixels that motion changes: f2's motion blur %.4f levels, its sharp frame %.4f\n",
        movingCount, meanDifference(blurred, mean, moving), meanDifference(sharp, mean, moving));
    if (blurredOff > bound) return std::puts("FAIL: the blurred frame is further than the bound"), 1;
    if (sharpOff < 3 * blurredOff)
        return std::puts("FAIL: the sharp frame is nearly as close: the scene shows no blur"), 1;
    return 0;
}
