#pragma once
/// Renders frames of a scene: evaluate the animation at t, build the BVH,
/// trace the image in tiles over a persistent thread pool. Public API: no
/// SIMD type appears here, so users compile without the core's CPU flags.
#include <atomic>
#include <functional>
#include <limits>
#include <span>

#include "core/render/camera.h"
#include "core/render/image.h"
#include "core/render/linear_image.h"
#include "core/render/prepared_frame.h"
#include "core/render/primary_bins.h"
#include "core/render/ray_counts.h"
#include "core/render/view_mode.h"
#include "core/util/thread_pool.h"

namespace f2 {

struct RenderOptions {
    int antialias = 1;  ///< N: N x N stratified samples per pixel; 1 = pixel centre (SPEC 2)
    /// What the pixels show. The diagnostic modes trace one ray per pixel
    /// centre by the reference path (diagnostic_view.h); antialias is for Shaded.
    ViewMode view = ViewMode::Shaded;
    /// Only the image rows [firstRow, endRow) are traced, the others
    /// unwritten (a web page's worker renders a band); shaded view, render() only.
    int firstRow = 0;
    int endRow = std::numeric_limits<int>::max();
};

/// Wall-clock split of one frame, in milliseconds, and the rays it cast.
struct FrameTimings {
    double evaluateMs = 0, buildMs = 0, traceMs = 0;
    RayCounts rays;
    bool complete = true;  ///< false when cancelled: the image is partial
    double totalMs() const { return evaluateMs + buildMs + traceMs; }
};

/// One of the images a frame averages (motion blur): a scene time and the
/// camera at that time.
struct SubFrame {
    double time = 0;  ///< frames, may be fractional (or negative: the first keys hold)
    Camera camera;
};

/// Square tiles handed to threads, each rendered into a local buffer and then
/// copied out. 32 measured faster than 16 (robots:10000 +6 %, default +17 %)
/// and as fast as 64, which would balance worse on many cores.
inline constexpr int kTileSize = 32;

class Renderer {
   public:
    /// `threads` = 0 uses every core.
    explicit Renderer(int threads = 0);

    /// Traces a prepared frame (its BVH built) into `out` at the camera's size,
    /// in the view mode of `options` (depth and cost with their legend, view_legend.h).
    /// Returns false if `cancel` was raised (the image is then incomplete).
    bool trace(const PreparedFrame& frame, const Camera& camera, Image& out,
               const RenderOptions& options = {}, const std::atomic<bool>* cancel = nullptr,
               RayCounts* rays = nullptr);

    /// The whole frame: evaluate `scene` at time `t` (frames), build, trace,
    /// and in the shaded view draw the captions shown at `t` (captions.h).
    /// Reuses this renderer's frame buffers, so steady-state frames do not allocate.
    FrameTimings render(const SceneDesc& scene, double t, const Camera& camera, Image& out,
                        const RenderOptions& options = {}, const std::atomic<bool>* cancel = nullptr);

    /// The mean of the images of `subFrames` (motion blur; all at one image
    /// size): each is evaluated, built and traced as by render(), its pixels
    /// (the clamped mean of the anti-aliasing samples) added up in float in
    /// sub-frame order, and the mean converted to bytes once. The same bytes for
    /// any thread count; one sub-frame gives render()'s bytes. A diagnostic
    /// view (options.view) shows the middle sub-frame alone. `subFrameDone`
    /// (optional) is called on this thread after each sub-frame with the number done.
    /// `t` is the frame's own time: its captions (SPEC 10.5) are drawn sharp over the mean.
    FrameTimings renderAveraged(const SceneDesc& scene, double t, std::span<const SubFrame> subFrames,
                                Image& out, const RenderOptions& options = {},
                                const std::atomic<bool>* cancel = nullptr,
                                const std::function<void(int done)>& subFrameDone = {});

    /// Frames of at least this many primitives trace their primary rays from
    /// screen-space bins instead of the BVH where that is predicted to pay
    /// (PrimaryBins): the same images. For tests and measurements.
    void setPrimaryBinsFrom(std::size_t primitives) { primaryBinsFrom_ = primitives; }

    /// The frame evaluated by the last render().
    const PreparedFrame& frame() const { return frame_; }
    int threadCount() const { return pool_.threadCount(); }

   private:
    /// Evaluates `scene` at `t` into frame_ and updates its BVH (render()'s first two steps).
    void prepare(const SceneDesc& scene, double t, FrameTimings& timings);
    /// As trace(), but adds each pixel's colour (before the 8-bit conversion) to `sum`.
    bool traceAdding(const PreparedFrame& frame, const Camera& camera, LinearImage& sum,
                     const RenderOptions& options, const std::atomic<bool>* cancel, RayCounts* rays);

    ThreadPool pool_;
    PreparedFrame frame_;
    LinearImage sum_;          // renderAveraged's accumulator, kept for its capacity
    PrimaryBins primaryBins_;  // this frame's, rebuilt by each trace
    std::size_t primaryBinsFrom_ = PrimaryBins::kMinPrimitives;
};

/// Colour (0..1) of one pixel's sample at image point (px, py): the single-ray
/// reference path, used by tests and debugging.
Vec3 renderSample(const PreparedFrame& frame, const Camera& camera, float px, float py);

/// The whole image by the single-ray reference path, one thread, one sample per
/// pixel. The packet path of Renderer::trace must agree with it (tests).
void traceReference(const PreparedFrame& frame, const Camera& camera, Image& out);

/// The instruction set the core's packets were built for ("AVX-512",
/// "AVX2", "scalar") and their width in rays.
const char* packetIsaName();
int packetWidth();

}  // namespace f2
