#include "core/render/diagnostic_view.h"

#include <algorithm>
#include <vector>

#include "core/render/shading.h"

namespace f2 {

RayProbe probeRay(const PreparedFrame& frame, const Ray& ray, bool lights) {
    RayProbe probe;
    probe.lights = int(frame.lights.size() + frame.localLights.size());
    HitRecord hit;
    if (!frame.bvh.intersect(ray, primaryRayStart(ray.origin), kInfinity, hit, probe.cost)) return probe;
    probe.hit = true;
    probe.distance = hit.t;
    probe.primitive = hit.primitive;
    probe.normal = shadingPoint(frame, ray, hit).normal;
    if (!lights) return probe;
    // The shading's own shadow rays, so the mask and the cost are what the image used.
    shadeHit(
        frame, ray, hit,
        [&](const LightTerm& term) {
            if (term.rays == 0) return;  // faces away, or outside a spot's cone
            probe.shadowRays += term.rays;
            // A soft light counts by the fraction of its samples that reach the point.
            const float seen = term.shadowed ? 0.0f : term.visible;
            probe.lit += seen;
            probe.blocked += 1.0f - seen;
        },
        probe.cost);
    return probe;
}

Rgb8 normalColor(const RayProbe& probe) {
    if (!probe.hit) return {0, 0, 0};
    const Vec3 n = probe.normal;
    return {toByte((n.x + 1.0f) * 0.5f), toByte((n.y + 1.0f) * 0.5f), toByte((n.z + 1.0f) * 0.5f)};
}

Rgb8 shadowMaskColor(const RayProbe& probe) {
    if (!probe.hit) return kMaskBackground;
    if (probe.lights == 0) return {0, 0, 0};
    const float n = float(probe.lights);
    const float lit = probe.lit / n, blocked = probe.blocked / n;
    return {toByte(lit + blocked), toByte(lit), toByte(lit)};
}

Rgb8 primitiveIdColor(std::uint32_t primitive) {
    // The finaliser of MurmurHash3 over index + 1: neighbouring indices get
    // unrelated colours, and each channel stays in [48, 255] so no primitive
    // is as dark as the background.
    std::uint32_t h = primitive + 1;
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    auto channel = [h](int shift) { return std::uint8_t(48 + ((h >> shift) & 0xFFu) * 207 / 255); };
    return {channel(0), channel(8), channel(16)};
}

Rgb8 depthColor(float distance, float nearest, float farthest) {
    // Linear in 1/distance, as perspective is: a floor running to the horizon
    // spreads over the whole ramp instead of leaving the near objects one grey.
    const float g = farthest > nearest ? 0.1f + 0.9f * (nearest / distance - nearest / farthest) /
                                                    (1.0f - nearest / farthest)
                                       : 1.0f;
    const std::uint8_t v = toByte(g);
    return {v, v, v};
}

Vec3 heatRamp(float v) {
    // Stops at 0, 1/4, 1/2, 3/4, 1, linear in between.
    static constexpr Vec3 kStops[] = {{0, 0, 0}, {0.25f, 0, 0.5f}, {0.75f, 0, 0.5f}, {1, 0.5f, 0}, {1, 1, 1}};
    constexpr int kLast = int(std::size(kStops)) - 1;
    const float x = std::clamp(v, 0.0f, 1.0f) * float(kLast);
    const int i = std::min(int(x), kLast - 1);
    const float f = x - float(i);
    return kStops[i] * (1.0f - f) + kStops[i + 1] * f;
}

Rgb8 costColor(std::uint32_t cost, std::uint32_t maxCost) {
    const Vec3 c = heatRamp(maxCost > 0 ? float(cost) / float(maxCost) : 0.0f);
    return {toByte(c.x), toByte(c.y), toByte(c.z)};
}

bool traceView(const PreparedFrame& frame, const Camera& camera, ViewMode mode, Image& out, ThreadPool* pool,
               const std::atomic<bool>* cancel, ViewRange* range, RayCounts* rays) {
    out.resize(camera.width, camera.height);
    const bool scaled = mode == ViewMode::Depth || mode == ViewMode::Cost;
    // Depth and cost are scaled by the whole image's range: a first pass keeps
    // each pixel's value (a distance, -1 for the background; or a cost).
    std::vector<float> values(scaled ? out.pixels.size() : 0);
    std::atomic<bool> cancelled{false};
    std::atomic<std::uint64_t> shadowRays{0};
    const bool lights = mode == ViewMode::ShadowMask || mode == ViewMode::Cost;
    auto stopped = [&] {
        if (!cancel || !cancel->load(std::memory_order_relaxed)) return false;
        cancelled.store(true, std::memory_order_relaxed);
        return true;
    };
    auto row = [&](std::uint32_t y) {
        std::uint64_t rowShadowRays = 0;
        for (int x = 0; x < camera.width; ++x) {
            // Per pixel where lights are traced: a row under 1,000 soft lights takes seconds.
            if ((x == 0 || lights) && stopped()) return;
            const RayProbe p = probeRay(frame, camera.rayThrough(float(x) + 0.5f, float(y) + 0.5f), lights);
            rowShadowRays += p.shadowRays;
            const std::size_t i = std::size_t(y) * std::size_t(camera.width) + std::size_t(x);
            switch (mode) {
                case ViewMode::Normals:
                    out.pixels[i] = normalColor(p);
                    break;
                case ViewMode::ShadowMask:
                    out.pixels[i] = shadowMaskColor(p);
                    break;
                case ViewMode::PrimitiveIds:
                    out.pixels[i] = p.hit ? primitiveIdColor(p.primitive) : Rgb8{0, 0, 0};
                    break;
                case ViewMode::Depth:
                    values[i] = p.hit ? p.distance : -1.0f;
                    break;
                case ViewMode::Cost:
                    values[i] = float(p.cost.total());
                    break;
                case ViewMode::Shaded:
                    break;
            }
        }
        shadowRays.fetch_add(rowShadowRays, std::memory_order_relaxed);
    };
    if (pool) {
        pool->parallelFor(std::uint32_t(camera.height), row);
    } else {
        for (int y = 0; y < camera.height; ++y) row(std::uint32_t(y));
    }
    if (rays) *rays = {std::uint64_t(out.pixels.size()), shadowRays.load()};
    if (cancelled.load()) return false;

    ViewRange r;
    if (mode == ViewMode::Depth) {
        bool any = false;
        for (float d : values) {
            if (d < 0) continue;
            r.low = any ? std::min(r.low, d) : d;
            r.high = any ? std::max(r.high, d) : d;
            any = true;
        }
        for (std::size_t i = 0; i < values.size(); ++i)
            out.pixels[i] = values[i] < 0 ? Rgb8{0, 0, 0} : depthColor(values[i], r.low, r.high);
    } else if (mode == ViewMode::Cost && !values.empty()) {
        const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
        r = {*lo, *hi};
        for (std::size_t i = 0; i < values.size(); ++i)
            out.pixels[i] = costColor(std::uint32_t(values[i]), std::uint32_t(r.high));
    }
    if (range) *range = r;
    return true;
}

}  // namespace f2
