#include "core/render/renderer.h"

#include <chrono>

#include "core/anim/frame_builder.h"
#include "core/render/packet_shading.h"
#include "core/render/shading.h"

namespace f2 {

namespace {
using Clock = std::chrono::steady_clock;
double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}
}  // namespace

Renderer::Renderer(int threads) : pool_(threads) {}

Vec3 renderSample(const FrameScene& frame, const Camera& camera, float px, float py) {
    return traceRay(frame, camera.rayThrough(px, py));
}

namespace {
// A packet covers a block of kBlockWidth x kBlockHeight pixels (4x4 with
// AVX-512, 4x2 with AVX2, 1x1 without SIMD); tiles are whole blocks.
constexpr int kBlockWidth = simd::kWidth >= 4 ? 4 : 1;
constexpr int kBlockHeight = simd::kWidth / kBlockWidth;
static_assert(kTileSize % kBlockWidth == 0 && kTileSize % kBlockHeight == 0);

// Entry nodes per tile (Bvh::entryNodes): each costs every packet one box test.
constexpr std::size_t kEntryNodes = 8;

struct LaneOffsets {
    Float x, y;
    LaneOffsets() {
        alignas(64) float xs[simd::kWidth], ys[simd::kWidth];
        for (int i = 0; i < simd::kWidth; ++i) {
            xs[i] = float(i % kBlockWidth);
            ys[i] = float(i / kBlockWidth);
        }
        x = simd::load(xs);
        y = simd::load(ys);
    }
};

/// Primary rays through image points (px, py); the lane version of Camera::rayThrough.
EyeRays primaryRays(const Camera& camera, Float px, Float py) {
    Float x = px * Float(camera.inverseWidth()) - Float(0.5f);
    Float y = (Float(0.5f) - py * Float(camera.inverseHeight())) * Float(camera.aspect());
    Vec3P v(x, y, Float(camera.distance));
    v = v * (Float(1.0f) / simd::sqrt(dot(v, v)));
    const Mat3& m = camera.worldFromCamera;
    Vec3P d(dot(Vec3P(m.row[0]), v), dot(Vec3P(m.row[1]), v), dot(Vec3P(m.row[2]), v));
    return EyeRays(camera.eye, d);
}

ColorP clamped(const ColorP& c) {
    auto unit = [](Float v) { return simd::min(simd::max(v, Float(0.0f)), Float(1.0f)); };
    return {unit(c.r), unit(c.g), unit(c.b)};
}

/// Renders one block of pixels with its top-left corner at (x0, y0) into
/// `dst` (that corner's pixel; rows `stride` pixels apart).
void renderBlock(const FrameScene& frame, const Camera& camera, int aa, const LaneOffsets& lanes, int x0, int y0,
                 std::span<const std::uint32_t> entry, Rgb8* dst, int stride, RayCounts& counts) {
    Float px = Float(float(x0)) + lanes.x, py = Float(float(y0)) + lanes.y;
    Mask inside = (px < Float(float(camera.width))) & (py < Float(float(camera.height)));
    ColorP c;
    if (aa == 1) {
        c = tracePacket(frame, camera.eye, primaryRays(camera, px + Float(0.5f), py + Float(0.5f)), inside, entry,
                        counts);
    } else {
        // Stratified: the centre of each of the N x N sub-cells, clamped per sample
        // so the result is the average of displayed values.
        c = {Float(0.0f), Float(0.0f), Float(0.0f)};
        for (int sy = 0; sy < aa; ++sy) {
            for (int sx = 0; sx < aa; ++sx) {
                Float ox((float(sx) + 0.5f) / float(aa)), oy((float(sy) + 0.5f) / float(aa));
                ColorP s =
                    clamped(tracePacket(frame, camera.eye, primaryRays(camera, px + ox, py + oy), inside, entry, counts));
                c = {c.r + s.r, c.g + s.g, c.b + s.b};
            }
        }
        Float weight(1.0f / float(aa * aa));
        c = {c.r * weight, c.g * weight, c.b * weight};
    }
    alignas(64) std::int32_t r[simd::kWidth], g[simd::kWidth], b[simd::kWidth];
    simd::store(r, toBytes(c.r));
    simd::store(g, toBytes(c.g));
    simd::store(b, toBytes(c.b));
    const int w = std::min(kBlockWidth, camera.width - x0), h = std::min(kBlockHeight, camera.height - y0);
    for (int row = 0; row < h; ++row, dst += stride) {
        for (int col = 0; col < w; ++col) {
            int i = row * kBlockWidth + col;
            dst[col] = {std::uint8_t(r[i]), std::uint8_t(g[i]), std::uint8_t(b[i])};
        }
    }
}
}  // namespace

bool Renderer::trace(const FrameScene& frame, const Camera& camera, Image& out, const RenderOptions& options,
                     const std::atomic<bool>* cancel, RayCounts* rays) {
    out.resize(camera.width, camera.height);
    const int tilesX = (camera.width + kTileSize - 1) / kTileSize;
    const int tilesY = (camera.height + kTileSize - 1) / kTileSize;
    const int aa = options.antialias < 1 ? 1 : options.antialias;
    static const LaneOffsets lanes;
    std::atomic<bool> cancelled{false};
    std::atomic<std::uint64_t> primaryRays{0}, shadowRays{0};

    pool_.parallelFor(std::uint32_t(tilesX * tilesY), [&](std::uint32_t tile) {
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            cancelled.store(true, std::memory_order_relaxed);
            return;
        }
        const int x0 = int(tile % std::uint32_t(tilesX)) * kTileSize;
        const int y0 = int(tile / std::uint32_t(tilesX)) * kTileSize;
        const int x1 = std::min(x0 + kTileSize, camera.width);
        const int y1 = std::min(y0 + kTileSize, camera.height);
        // The tile is rendered into a local buffer and copied out whole: the
        // image rows of neighbouring tiles share cache lines, which two threads
        // writing pixel by pixel would pass back and forth.
        Rgb8 local[kTileSize * kTileSize];
        // The tile's packets start below the top of the tree, at the nodes its frustum reaches.
        std::uint32_t entryStore[kEntryNodes];
        std::span<const std::uint32_t> entry(
            entryStore, frame.bvh.entryNodes(camera.pixelFrustum(x0, y0, x1, y1), camera.eye, entryStore));
        RayCounts tileRays;
        for (int y = y0; y < y1; y += kBlockHeight)
            for (int x = x0; x < x1; x += kBlockWidth)
                renderBlock(frame, camera, aa, lanes, x, y, entry, &local[(y - y0) * kTileSize + (x - x0)],
                            kTileSize, tileRays);
        for (int y = y0; y < y1; ++y)
            std::copy_n(&local[(y - y0) * kTileSize], x1 - x0, &out.at(x0, y));
        primaryRays.fetch_add(tileRays.primary, std::memory_order_relaxed);
        shadowRays.fetch_add(tileRays.shadow, std::memory_order_relaxed);
    });
    if (rays) *rays = {primaryRays.load(), shadowRays.load()};
    return !cancelled.load();
}

/// The single-ray reference path over the whole image (tests compare it with trace()).
void traceReference(const FrameScene& frame, const Camera& camera, Image& out) {
    out.resize(camera.width, camera.height);
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            Vec3 c = renderSample(frame, camera, float(x) + 0.5f, float(y) + 0.5f);
            out.at(x, y) = {toByte(c.x), toByte(c.y), toByte(c.z)};
        }
}

FrameTimings Renderer::render(const SceneDesc& scene, double t, const Camera& camera, Image& out,
                              const RenderOptions& options, const std::atomic<bool>* cancel) {
    FrameTimings timings;
    auto start = Clock::now();
    evaluateFrame(scene, t, frame_, &pool_);
    timings.evaluateMs = millisecondsSince(start);

    start = Clock::now();
    frame_.bvh.update(frame_.primitives, &pool_);
    timings.buildMs = millisecondsSince(start);

    start = Clock::now();
    timings.complete = trace(frame_, camera, out, options, cancel, &timings.rays);
    timings.traceMs = millisecondsSince(start);
    return timings;
}

}  // namespace f2
