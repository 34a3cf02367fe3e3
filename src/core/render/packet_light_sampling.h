#pragma once
/// Lane version of light_sampling.h: the shadow tests of soft suns and of
/// point and spot lights for a whole packet, operation for operation as the
/// reference path. Private to the core (SIMD types).
#include "core/geometry/bvh_packet.h"
#include "core/render/light_sampling.h"
#include "core/render/ray_counts.h"

namespace f2 {

inline Vec3P divide(const Vec3P& v, Float s) { return {v.x / s, v.y / s, v.z / s}; }
inline Vec3P cross(const Vec3P& a, const Vec3P& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// As normalize() in vec3.h: v * (1 / |v|).
inline Vec3P normalize(const Vec3P& v) { return v * (Float(1.0f) / simd::sqrt(dot(v, v))); }

inline std::uint64_t laneCount(Mask m) { return std::uint64_t(__builtin_popcount(simd::bits(m))); }

/// visibleSunSamples() for the `lit` lanes; the shadow rays start from
/// `entry` (Bvh::beamEntryNodes of the tile's origins along the samples).
inline Int visibleSunSamplesP(const PreparedFrame& frame, const LightSample& light, const Vec3P& origin,
                              const Vec3P& normal, Int skip, Mask lit, std::span<const std::uint32_t> entry,
                              RayCounts& counts) {
    Int visible(0);
    for (std::uint32_t k = 0; k < light.sampleCount; ++k) {
        const Vec3 toSample = frame.sunDirections[light.firstSample + k];
        const Mask lanes = lit & (dot(normal, toSample) > Float(0.0f));
        if (simd::none(lanes)) continue;
        counts.shadow += laneCount(lanes);
        const Mask reach =
            simd::andNot(lanes, occludedPacket(frame.bvh, ParallelRays(origin, toSample), lanes, Float(0.0f),
                                               Float(kInfinity), skip, entry));
        visible = simd::select(reach, visible + Int(1), visible);
    }
    return visible;
}

/// viewLocalLight() per lane.
struct LocalLightViewP {
    Vec3P toLight;
    Float distance;
};
inline LocalLightViewP viewLocalLightP(const LocalLightSample& light, const Vec3P& origin) {
    const Vec3P v = light.position - origin;
    const Float distance = simd::sqrt(dot(v, v));
    return {divide(v, distance), distance};
}

/// localLightIntensity() for the `lit` lanes (0 elsewhere). A spot's cone and
/// fade take pow(), which is done lane by lane with the reference's own
/// function, so both paths give the same bits.
inline Float localLightIntensityP(const LocalLightSample& light, const LocalLightViewP& view, Mask lit) {
    if (!light.spot && !light.fade.fades()) return simd::select(lit, Float(light.intensity), Float(0.0f));
    alignas(64) float cosAngle[simd::kWidth], distance[simd::kWidth], out[simd::kWidth];
    simd::store(cosAngle, -dot(view.toLight, light.axis));
    simd::store(distance, view.distance);
    const std::uint32_t bits = simd::bits(lit);
    for (int i = 0; i < simd::kWidth; ++i)
        out[i] = (bits >> i) & 1u ? localLightIntensity(light, cosAngle[i], distance[i]) : 0.0f;
    return simd::load(out);
}

/// Lanes of `active` whose point light is hidden: localLightBlocked() per lane.
inline Mask localLightBlockedP(const PreparedFrame& frame, const LocalLightSample& light,
                               const LocalLightViewP& view, Int skip, Mask active, RayCounts& counts) {
    counts.shadow += laneCount(active);
    return occludedPacket(frame.bvh, EyeRays(light.position, -view.toLight), active, Float(0.0f),
                          view.distance, skip);
}

/// visibleDiscSamples() for the `active` lanes.
inline Int visibleDiscSamplesP(const PreparedFrame& frame, const LocalLightSample& light,
                               const LocalLightViewP& view, const Vec3P& origin, const Vec3P& normal,
                               Int skip, Mask active, RayCounts& counts) {
    // discAxes() per lane.
    const Mask nearZ = simd::abs(simd::abs(view.toLight.z) - Float(1.0f)) < Float(0.01f);
    const Vec3P helper = select(nearZ, Vec3P(Vec3{0, 1, 0}), Vec3P(Vec3{0, 0, 1}));
    const Vec3P axisA = normalize(cross(view.toLight, helper));
    const Vec3P axisB = normalize(cross(view.toLight, axisA));
    const Vec3P a = axisA * Float(light.diameter), b = axisB * Float(light.diameter);
    Int visible(0);
    for (std::uint32_t k = 0; k < light.sampleCount; ++k) {
        const DiscPoint d = frame.discPoints[light.firstSample + k];
        const Vec3P sample = light.position + a * Float(d.u) + b * Float(d.v);
        const Vec3P w = origin - sample;
        const Float length = simd::sqrt(dot(w, w));
        const Vec3P direction = divide(w, length);
        const Mask lanes = active & (dot(normal, direction) < Float(0.0f));
        if (simd::none(lanes)) continue;
        counts.shadow += laneCount(lanes);
        const Mask reach = simd::andNot(
            lanes, occludedPacket(frame.bvh, FreeRays(sample, direction), lanes, Float(0.0f), length, skip));
        visible = simd::select(reach, visible + Int(1), visible);
    }
    return visible;
}

}  // namespace f2
