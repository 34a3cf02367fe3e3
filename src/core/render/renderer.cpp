#include "core/render/renderer.h"

#include <algorithm>
#include <chrono>
#include <new>

#include "core/anim/frame_builder.h"
#include "core/render/captions.h"
#include "core/render/diagnostic_view.h"
#include "core/render/frame_preparation.h"
#include "core/render/packet_reflection.h"
#include "core/render/packet_shading.h"
#include "core/render/reflection.h"
#include "core/render/shading.h"
#include "core/render/view_legend.h"
#include "core/util/elapsed.h"

namespace f2 {

Renderer::Renderer(int threads) : pool_(threads) {}

const char* packetIsaName() { return simd::kIsaName; }
int packetWidth() { return simd::kWidth; }

Vec3 renderSample(const PreparedFrame& frame, const Camera& camera, float px, float py) {
    return traceRay(frame, camera.rayThrough(px, py));
}

namespace {
// A packet covers a block of kBlockWidth x kBlockHeight pixels (4x4 with
// AVX-512, 4x2 with AVX2, 4x1 with wasm SIMD, 1x1 without SIMD); tiles are whole blocks.
constexpr int kBlockWidth = simd::kWidth >= 4 ? 4 : 1;
constexpr int kBlockHeight = simd::kWidth / kBlockWidth;
static_assert(kTileSize % kBlockWidth == 0 && kTileSize % kBlockHeight == 0);
static_assert(PrimaryBins::kCellWidth % kBlockWidth == 0 && PrimaryBins::kCellHeight % kBlockHeight == 0 &&
              kTileSize % PrimaryBins::kCellWidth == 0 && kTileSize % PrimaryBins::kCellHeight == 0);

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

constexpr int kBlocksPerTile = (kTileSize / kBlockWidth) * (kTileSize / kBlockHeight);
// Lights whose shadow rays start from per-tile entry nodes; any further ones start from the root.
constexpr std::size_t kShadowEntryLights = 4;

/// Renders one tile in passes over its blocks: per sample, the primary rays
/// of every block first, then the shadow rays, which then all start from the
/// BVH nodes that the beam of their origins toward each light reaches.
class TileRenderer {
   public:
    /// `bins`: this frame's PrimaryBins for `camera`, or null to walk the BVH.
    TileRenderer(const PreparedFrame& frame, const Camera& camera, const PrimaryBins* bins, int aa,
                 RayCounts& counts)
        : frame_(frame), camera_(camera), bins_(bins), aa_(aa), counts_(counts) {}

    /// Pixels [x0, x1) x [y0, y1) into `dst` (kTileSize pixels per row).
    /// False, with `dst` incomplete, if `cancel` was raised: checked before
    /// each sample pass, as one tile with --aa 16 and many lights takes seconds.
    bool render(int x0, int y0, int x1, int y1, Rgb8* dst, const std::atomic<bool>* cancel) {
        return renderBlocks(x0, y0, x1, y1, cancel, [dst](const ColorP& c, int w, int h, int offset) {
            writeBlock(c, w, h, dst + offset);
        });
    }

    /// As render(), but the colours before the 8-bit conversion, clamped to
    /// [0, 1] as displayed (so that averages are of what each sample shows).
    bool render(int x0, int y0, int x1, int y1, LinearRgb* dst, const std::atomic<bool>* cancel) {
        return renderBlocks(x0, y0, x1, y1, cancel, [dst](const ColorP& c, int w, int h, int offset) {
            writeLinearBlock(clamped(c), w, h, dst + offset);
        });
    }

   private:
    /// The tile's pixels, handed block by block to write(colour, width, height,
    /// offset of the block's first pixel in a kTileSize-wide buffer).
    template <class WriteBlock>
    bool renderBlocks(int x0, int y0, int x1, int y1, const std::atomic<bool>* cancel, WriteBlock&& write) {
        static const LaneOffsets lanes;
        // The tile's primary packets start below the top of the tree, at the nodes its frustum
        // reaches; or, in a binned frame, at those listed everywhere and in their cells.
        std::uint32_t entryStore[kEntryNodes];
        std::span<const std::uint32_t> entry =
            bins_ ? bins_->everywhere()
                  : std::span<const std::uint32_t>(
                        entryStore,
                        frame_.bvh.entryNodes(camera_.pixelFrustum(x0, y0, x1, y1), camera_.eye, entryStore));
        const int blocksX = (x1 - x0 + kBlockWidth - 1) / kBlockWidth;
        const int blocksY = (y1 - y0 + kBlockHeight - 1) / kBlockHeight;
        const int blocks = blocksX * blocksY;
        for (int sy = 0; sy < aa_; ++sy) {
            for (int sx = 0; sx < aa_; ++sx) {
                if (cancel && cancel->load(std::memory_order_relaxed)) return false;
                // One sample: the pixel centre, or the centre of sub-cell (sx, sy) of N x N.
                Float ox((float(sx) + 0.5f) / float(aa_)), oy((float(sy) + 0.5f) / float(aa_));
                Vec3P lo(Vec3{kInfinity, kInfinity, kInfinity}), hi(Vec3{-kInfinity, -kInfinity, -kInfinity});
                for (int k = 0; k < blocks; ++k) {
                    const int bx = x0 + (k % blocksX) * kBlockWidth, by = y0 + (k / blocksX) * kBlockHeight;
                    Float px = Float(float(bx)) + lanes.x;
                    Float py = Float(float(by)) + lanes.y;
                    Mask inside = (px < Float(float(camera_.width))) & (py < Float(float(camera_.height)));
                    const std::span<const std::uint32_t> cell =
                        bins_ ? bins_->cell(bx, by) : std::span<const std::uint32_t>();
                    // Built in place (a prvalue into placement new): assigned, the surface
                    // would be built aside and copied in, a call to memcpy in wasm.
                    new (&surfaces_[k]) PacketSurface(findSurfaces(
                        frame_, primaryRays(camera_, px + ox, py + oy), inside, entry, cell, counts_));
                    const PacketSurface& s = surfaces_[k];
                    lo = select(s.hitLanes, vmin(s.shadowOrigin, lo), lo);
                    hi = select(s.hitLanes, vmax(s.shadowOrigin, hi), hi);
                }
                ShadowEntries shadowEntry(frame_, lo, hi);
                for (int k = 0; k < blocks; ++k) {
                    // Also per block: under 1,000 soft lights (256 shadow rays each) one
                    // sample pass of a tile takes seconds, and Ctrl+C must stop within one.
                    if (cancel && cancel->load(std::memory_order_relaxed)) return false;
                    ColorP c = shadeSurfaces(frame_, surfaces_[k], shadowEntry.perLight(), counts_);
                    c = withReflections(frame_, surfaces_[k], c, counts_);
                    if (aa_ > 1) c = clamped(c);  // the average of displayed values
                    sum_[k] =
                        sx == 0 && sy == 0 ? c : ColorP{sum_[k].r + c.r, sum_[k].g + c.g, sum_[k].b + c.b};
                }
            }
        }
        Float weight(1.0f / float(aa_ * aa_));
        for (int k = 0; k < blocks; ++k) {
            ColorP c = sum_[k];
            if (aa_ > 1) c = {c.r * weight, c.g * weight, c.b * weight};
            const int bx = (k % blocksX) * kBlockWidth, by = (k / blocksX) * kBlockHeight;
            write(c, std::min(kBlockWidth, x1 - x0 - bx), std::min(kBlockHeight, y1 - y0 - by),
                  by * kTileSize + bx);
        }
        return true;
    }

    /// Per light, the entry nodes of the shadow rays leaving the box [lo, hi]
    /// (lane-wise bounds of the tile's shadow origins).
    class ShadowEntries {
       public:
        ShadowEntries(const PreparedFrame& frame, const Vec3P& lo, const Vec3P& hi) {
            const Bounds origins{{simd::minLane(lo.x), simd::minLane(lo.y), simd::minLane(lo.z)},
                                 {simd::maxLane(hi.x), simd::maxLane(hi.y), simd::maxLane(hi.z)}};
            if (!(origins.lo.x <= origins.hi.x)) return;  // nothing was hit: no shadow rays
            count_ = std::min(frame.lights.size(), kShadowEntryLights);
            for (std::size_t i = 0; i < count_; ++i) {
                const LightSample& light = frame.lights[i];
                // A soft sun's samples all start from the nodes that one of its directions reaches.
                const std::span<const Vec3> samples =
                    light.sampleCount == 0
                        ? std::span<const Vec3>()
                        : std::span(&frame.sunDirections[light.firstSample], light.sampleCount);
                const std::size_t n = light.sampleCount == 0
                                          ? frame.bvh.beamEntryNodes(origins, light.toLight, store_[i])
                                          : frame.bvh.beamEntryNodes(origins, samples, store_[i]);
                entries_[i].nodes = {store_[i], n};
                // Each packet narrows these nodes to its own beam toward all the samples (packetEntryNodes).
                for (const Vec3 d : samples) {
                    entries_[i].directions.lo = vmin(entries_[i].directions.lo, d);
                    entries_[i].directions.hi = vmax(entries_[i].directions.hi, d);
                }
                entries_[i].slack = beamSlack(frame.bvh);
            }
        }
        std::span<const LightEntry> perLight() const { return {entries_, count_}; }

       private:
        std::uint32_t store_[kShadowEntryLights][kEntryNodes];
        LightEntry entries_[kShadowEntryLights];
        std::size_t count_ = 0;
    };

    static void writeBlock(const ColorP& c, int w, int h, Rgb8* dst) {
        alignas(64) std::int32_t r[simd::kWidth], g[simd::kWidth], b[simd::kWidth];
        simd::store(r, toBytes(c.r));
        simd::store(g, toBytes(c.g));
        simd::store(b, toBytes(c.b));
        for (int row = 0; row < h; ++row, dst += kTileSize) {
            for (int col = 0; col < w; ++col) {
                int i = row * kBlockWidth + col;
                dst[col] = {std::uint8_t(r[i]), std::uint8_t(g[i]), std::uint8_t(b[i])};
            }
        }
    }

    static void writeLinearBlock(const ColorP& c, int w, int h, LinearRgb* dst) {
        alignas(64) float r[simd::kWidth], g[simd::kWidth], b[simd::kWidth];
        simd::store(r, c.r);
        simd::store(g, c.g);
        simd::store(b, c.b);
        for (int row = 0; row < h; ++row, dst += kTileSize) {
            for (int col = 0; col < w; ++col) {
                int i = row * kBlockWidth + col;
                dst[col] = {r[i], g[i], b[i]};
            }
        }
    }

    const PreparedFrame& frame_;
    const Camera& camera_;
    const PrimaryBins* bins_;
    const int aa_;
    RayCounts& counts_;
    PacketSurface surfaces_[kBlocksPerTile];
    ColorP sum_[kBlocksPerTile];
};
}  // namespace

namespace {
/// Runs `renderTile(x0, y0, x1, y1, rays)` for every tile of the camera's image
/// that has a row in [firstRow, endRow), on the pool; false if any tile was
/// cancelled (renderTile returned false).
template <class RenderTile>
bool forEachTile(ThreadPool& pool, const Camera& camera, int firstRow, int endRow, RayCounts* rays,
                 RenderTile&& renderTile) {
    const int tilesX = (camera.width + kTileSize - 1) / kTileSize;
    const int firstTileRow = std::max(firstRow, 0) / kTileSize;
    const int tilesY =
        std::max((std::min(endRow, camera.height) + kTileSize - 1) / kTileSize - firstTileRow, 0);
    std::atomic<bool> cancelled{false};
    std::atomic<std::uint64_t> primaryRays{0}, shadowRays{0}, reflectedRays{0};

    pool.parallelFor(std::uint32_t(tilesX * tilesY), [&](std::uint32_t tile) {
        const int x0 = int(tile % std::uint32_t(tilesX)) * kTileSize;
        const int y0 = (int(tile / std::uint32_t(tilesX)) + firstTileRow) * kTileSize;
        const int x1 = std::min(x0 + kTileSize, camera.width);
        const int y1 = std::min(y0 + kTileSize, camera.height);
        RayCounts tileRays;
        if (!renderTile(x0, y0, x1, y1, tileRays)) {
            cancelled.store(true, std::memory_order_relaxed);
            return;
        }
        primaryRays.fetch_add(tileRays.primary, std::memory_order_relaxed);
        shadowRays.fetch_add(tileRays.shadow, std::memory_order_relaxed);
        reflectedRays.fetch_add(tileRays.reflected, std::memory_order_relaxed);
    });
    if (rays) *rays = {primaryRays.load(), shadowRays.load(), reflectedRays.load()};
    return !cancelled.load();
}
}  // namespace

bool Renderer::trace(const PreparedFrame& frame, const Camera& camera, Image& out,
                     const RenderOptions& options, const std::atomic<bool>* cancel, RayCounts* rays) {
    if (options.view != ViewMode::Shaded) {
        ViewRange range;
        if (!traceView(frame, camera, options.view, out, &pool_, cancel, &range, rays)) return false;
        drawViewLegend(out, options.view, range);
        return true;
    }
    out.resize(camera.width, camera.height);
    const int aa = options.antialias < 1 ? 1 : options.antialias;
    primaryBins_.build(frame.bvh, camera, &pool_, primaryBinsFrom_);
    const PrimaryBins* bins = primaryBins_.active() ? &primaryBins_ : nullptr;
    const int firstRow = options.firstRow, endRow = options.endRow;
    return forEachTile(
        pool_, camera, firstRow, endRow, rays, [&](int x0, int y0, int x1, int y1, RayCounts& tileRays) {
            // The tile is rendered into a local buffer and copied out whole (but the
            // rows outside the band): the image rows of neighbouring tiles share cache
            // lines, which two threads writing pixel by pixel would pass back and forth.
            Rgb8 local[kTileSize * kTileSize];
            if (!TileRenderer(frame, camera, bins, aa, tileRays).render(x0, y0, x1, y1, local, cancel))
                return false;
            for (int y = std::max(y0, firstRow); y < std::min(y1, endRow); ++y)
                std::copy_n(&local[(y - y0) * kTileSize], x1 - x0, &out.at(x0, y));
            return true;
        });
}

bool Renderer::traceAdding(const PreparedFrame& frame, const Camera& camera, LinearImage& sum,
                           const RenderOptions& options, const std::atomic<bool>* cancel, RayCounts* rays) {
    const int aa = options.antialias < 1 ? 1 : options.antialias;
    primaryBins_.build(frame.bvh, camera, &pool_, primaryBinsFrom_);
    const PrimaryBins* bins = primaryBins_.active() ? &primaryBins_ : nullptr;
    return forEachTile(
        pool_, camera, 0, camera.height, rays, [&](int x0, int y0, int x1, int y1, RayCounts& tileRays) {
            LinearRgb local[kTileSize * kTileSize];
            if (!TileRenderer(frame, camera, bins, aa, tileRays).render(x0, y0, x1, y1, local, cancel))
                return false;
            // Each pixel belongs to one tile, so the sums do not depend on the thread that adds.
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    const LinearRgb& c = local[(y - y0) * kTileSize + (x - x0)];
                    LinearRgb& s = sum.at(x, y);
                    s = {s.r + c.r, s.g + c.g, s.b + c.b};
                }
            return true;
        });
}

/// The single-ray reference path over the whole image (tests compare it with trace()).
void traceReference(const PreparedFrame& frame, const Camera& camera, Image& out) {
    out.resize(camera.width, camera.height);
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            Vec3 c = renderSample(frame, camera, float(x) + 0.5f, float(y) + 0.5f);
            out.at(x, y) = {toByte(c.x), toByte(c.y), toByte(c.z)};
        }
}

void Renderer::prepare(const SceneDesc& scene, double t, FrameTimings& timings) {
    const PreparationTimes times = prepareFrame(scene, t, frame_, &pool_);
    timings.evaluateMs += times.evaluateMs;
    timings.buildMs += times.buildMs;
}

FrameTimings Renderer::render(const SceneDesc& scene, double t, const Camera& camera, Image& out,
                              const RenderOptions& options, const std::atomic<bool>* cancel) {
    FrameTimings timings;
    prepare(scene, t, timings);
    const auto start = Clock::now();
    timings.complete = trace(frame_, camera, out, options, cancel, &timings.rays);
    // Captions are part of the picture, not of a diagnostic view (SPEC 10.5).
    if (timings.complete && options.view == ViewMode::Shaded) drawCaptions(out, scene.captions, t);
    timings.traceMs = millisecondsSince(start);
    return timings;
}

FrameTimings Renderer::renderAveraged(const SceneDesc& scene, double t, std::span<const SubFrame> subFrames,
                                      Image& out, const RenderOptions& options,
                                      const std::atomic<bool>* cancel,
                                      const std::function<void(int)>& subFrameDone) {
    FrameTimings timings;
    if (subFrames.empty()) return timings;
    // A diagnostic view shows one instant (depths or costs do not average): the middle sub-frame.
    if (options.view != ViewMode::Shaded) {
        const SubFrame& middle = subFrames[subFrames.size() / 2];
        return render(scene, middle.time, middle.camera, out, options, cancel);
    }
    const int width = subFrames.front().camera.width, height = subFrames.front().camera.height;
    sum_.resize(width, height);
    std::fill(sum_.pixels.begin(), sum_.pixels.end(), LinearRgb{});
    int done = 0;
    for (const SubFrame& sub : subFrames) {
        prepare(scene, sub.time, timings);
        const auto start = Clock::now();
        RayCounts rays;
        timings.complete =
            traceAdding(frame_, sub.camera.resized(width, height), sum_, options, cancel, &rays);
        timings.traceMs += millisecondsSince(start);
        timings.rays.primary += rays.primary;
        timings.rays.shadow += rays.shadow;
        if (!timings.complete) return timings;
        if (subFrameDone) subFrameDone(++done);
    }
    // The mean, rounded once.
    const auto start = Clock::now();
    out.resize(width, height);
    const float weight = 1.0f / float(subFrames.size());
    pool_.parallelFor(std::uint32_t(height), [&](std::uint32_t row) {
        const int y = int(row);
        for (int x = 0; x < width; ++x) {
            const LinearRgb& s = sum_.at(x, y);
            out.at(x, y) = {toByte(s.r * weight), toByte(s.g * weight), toByte(s.b * weight)};
        }
    });
    drawCaptions(out, scene.captions, t);  // sharp, at the frame's own time: they do not move
    timings.traceMs += millisecondsSince(start);
    return timings;
}

}  // namespace f2
