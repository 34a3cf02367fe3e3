#pragma once
/// The diagnostic view modes (view_mode.h): what the tracer finds along each
/// pixel's primary ray, as colours. They trace one ray through each pixel's
/// centre by the single-ray reference path (Bvh::intersect, shadeHit), so the
/// cost view counts that path's real traversal; --aa does not apply to them.
/// Each pixel is computed by one thread from the same inputs, and the ranges
/// (depth, cost) are minima and maxima: images do not depend on threads.
#include <atomic>
#include <cstdint>

#include "core/geometry/traversal_count.h"
#include "core/render/camera.h"
#include "core/render/image.h"
#include "core/render/prepared_frame.h"
#include "core/render/ray_counts.h"
#include "core/render/view_mode.h"
#include "core/util/thread_pool.h"

namespace f2 {

/// What one primary ray meets, by the reference path.
struct RayProbe {
    bool hit = false;             ///< false: the background
    float distance = 0;           ///< from the eye to the hit (the ray is unit length)
    Vec3 normal;                  ///< unit, turned to face the viewer (as shaded)
    std::uint32_t primitive = 0;  ///< the primitive hit, index in scene order
    int lights = 0;               ///< lights of the frame
    float lit = 0;                ///< of them, reaching the point (a soft light: the fraction of its samples)
    float blocked = 0;            ///< facing the point, but their shadow rays meet something (the fraction)
    TraversalCount cost;          ///< the primary ray's traversal plus every shadow ray's
    std::uint32_t shadowRays = 0;
};

/// Traces `ray` from the eye as traceRay() does (same start, same BVH query,
/// same shadow rays), recording instead of shading. Without `lights`, the
/// shadow rays are not cast (lit, blocked, shadowRays stay 0 and cost counts
/// the primary ray alone): the modes that do not show them run faster.
RayProbe probeRay(const PreparedFrame& frame, const Ray& ray, bool lights = true);

/// Normals view: floor(255·(n + 1)/2 + 0.5) per channel; background black.
Rgb8 normalColor(const RayProbe& probe);
/// Shadow-mask view: (lit + blocked, lit, lit) / lights; background kMaskBackground.
Rgb8 shadowMaskColor(const RayProbe& probe);
inline constexpr Rgb8 kMaskBackground{32, 32, 96};
/// Primitive-ids view: a colour hashed from the primitive's scene-order index.
Rgb8 primitiveIdColor(std::uint32_t primitive);
/// Depth view: grey 0.1 + 0.9·(near/d − near/far)/(1 − near/far) (1 when
/// far = near): linear in 1/d, the nearest white, the farthest 0.1.
Rgb8 depthColor(float distance, float nearest, float farthest);
/// Cost view: the heat ramp at cost / maxCost.
Rgb8 costColor(std::uint32_t cost, std::uint32_t maxCost);
/// The cost view's colour ramp, v in [0, 1]: black, indigo, purple, orange, white.
Vec3 heatRamp(float v);

/// The values a diagnostic image's colours were scaled by: depth's nearest and
/// farthest hit distance, cost's least and largest pixel cost (0, 0 when the
/// view has no scale or nothing was hit).
struct ViewRange {
    float low = 0, high = 0;
};

/// Renders diagnostic view `mode` (not Shaded) of `frame` into `out`, rows on
/// `pool` (serially without one). Returns false if `cancel` was raised.
bool traceView(const PreparedFrame& frame, const Camera& camera, ViewMode mode, Image& out,
               ThreadPool* pool = nullptr, const std::atomic<bool>* cancel = nullptr,
               ViewRange* range = nullptr, RayCounts* rays = nullptr);

}  // namespace f2
