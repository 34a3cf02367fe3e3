#include "core/render/renderer.h"

#include <chrono>

#include "core/anim/frame_builder.h"
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

bool Renderer::trace(const FrameScene& frame, const Camera& camera, Image& out, const RenderOptions& options,
                     const std::atomic<bool>* cancel) {
    out.resize(camera.width, camera.height);
    const int tilesX = (camera.width + kTileSize - 1) / kTileSize;
    const int tilesY = (camera.height + kTileSize - 1) / kTileSize;
    const int aa = options.antialias < 1 ? 1 : options.antialias;
    const float sampleWeight = 1.0f / float(aa * aa);
    std::atomic<bool> cancelled{false};

    pool_.parallelFor(std::uint32_t(tilesX * tilesY), [&](std::uint32_t tile) {
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            cancelled.store(true, std::memory_order_relaxed);
            return;
        }
        const int x0 = int(tile % std::uint32_t(tilesX)) * kTileSize;
        const int y0 = int(tile / std::uint32_t(tilesX)) * kTileSize;
        const int x1 = std::min(x0 + kTileSize, camera.width);
        const int y1 = std::min(y0 + kTileSize, camera.height);
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                Vec3 c;
                if (aa == 1) {
                    c = renderSample(frame, camera, float(x) + 0.5f, float(y) + 0.5f);
                } else {
                    // Stratified: the centre of each of the N x N sub-cells, so the
                    // image is deterministic and the same for any thread count.
                    for (int sy = 0; sy < aa; ++sy)
                        for (int sx = 0; sx < aa; ++sx) {
                            Vec3 s = renderSample(frame, camera, float(x) + (float(sx) + 0.5f) / float(aa),
                                                  float(y) + (float(sy) + 0.5f) / float(aa));
                            // Clamp per sample: the average of displayed values.
                            c += Vec3{std::clamp(s.x, 0.0f, 1.0f), std::clamp(s.y, 0.0f, 1.0f),
                                      std::clamp(s.z, 0.0f, 1.0f)};
                        }
                    c = c * sampleWeight;
                }
                out.at(x, y) = {toByte(c.x), toByte(c.y), toByte(c.z)};
            }
        }
    });
    return !cancelled.load();
}

FrameTimings Renderer::render(const SceneDesc& scene, double t, const Camera& camera, Image& out,
                              const RenderOptions& options, const std::atomic<bool>* cancel) {
    FrameTimings timings;
    auto start = Clock::now();
    evaluateFrame(scene, t, frame_);
    timings.evaluateMs = millisecondsSince(start);

    start = Clock::now();
    frame_.bvh.build(frame_.primitives);
    timings.buildMs = millisecondsSince(start);

    start = Clock::now();
    trace(frame_, camera, out, options, cancel);
    timings.traceMs = millisecondsSince(start);
    return timings;
}

}  // namespace f2
