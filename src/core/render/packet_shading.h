#pragma once
/// Phong shading of a whole packet (SPEC 3), the lane version of shading.h:
/// the same operations in the same order, except that pow() is the lane
/// approximation of simd_math.h (within 1e-6 relative).
#include "core/anim/frame_scene.h"
#include "core/render/shading.h"
#include "core/simd/simd_math.h"

namespace f2 {

struct ColorP {
    Float r, g, b;
};

/// Rays traced, counted as they are cast.
struct RayCounts {
    std::uint64_t primary = 0, shadow = 0;
    std::uint64_t total() const { return primary + shadow; }
};

/// Colours (0..1, unclamped) of the `active` lanes of a packet of primary rays
/// leaving the eye `eye`, all inside the frustum whose Bvh::entryNodes() are `entry`.
inline ColorP tracePacket(const FrameScene& frame, Vec3 eye, const EyeRays& rays, Mask active,
                          std::span<const std::uint32_t> entry, RayCounts& counts) {
    counts.primary += std::uint64_t(__builtin_popcount(simd::bits(active)));
    PacketHit hit;
    frame.bvh.intersect(rays, active, Float(primaryRayStart(eye)), hit, entry);
    Mask hitLanes = active & (hit.t < Float(kInfinity));

    ColorP out{Float(frame.background.x), Float(frame.background.y), Float(frame.background.z)};
    if (simd::none(hitLanes)) return out;

    // Gather each lane's surface: loop over the distinct primitives hit (few in a
    // coherent packet), filling their lanes from broadcast values. Hits name
    // primitives in the BVH's leaf order, whose copy is still in cache.
    const std::span<const Primitive> leafPrimitives = frame.bvh.orderedPrimitives();
    const std::span<const std::uint32_t> frameIndex = frame.bvh.originalIndices();
    Vec3P p = rays.origin + rays.direction * hit.t;
    Vec3P n, color;
    Float ka, kd, ks, shininess;
    alignas(64) std::int32_t primIds[simd::kWidth];
    simd::store(primIds, hit.primitive);
    for (Mask todo = hitLanes; simd::any(todo);) {
        std::int32_t id = primIds[simd::firstLane(todo)];
        Mask same = todo & (hit.primitive == Int(id));
        todo = simd::andNot(todo, same);
        const Surface& s = frame.surfaces[frameIndex[std::size_t(id)]];
        n = select(same, primitiveNormalP(leafPrimitives[std::size_t(id)], p, hit.face), n);
        color = select(same, Vec3P(s.color), color);
        ka = simd::select(same, Float(s.material.ka), ka);
        kd = simd::select(same, Float(s.material.kd), kd);
        ks = simd::select(same, Float(s.material.ks), ks);
        shininess = simd::select(same, Float(s.material.n), shininess);
    }
    Mask inside = dot(n, rays.direction) > Float(0.0f);  // seen from within the primitive
    n = select(inside, -n, n);                           // face the viewer
    // As in shadeHit(): shadow rays skip their own primitive only from its outside.
    Int skip = simd::select(inside, Int(-1), hit.primitive);
    Vec3P toEye = -rays.direction;
    Float offset = Float(kShadowBias) *
                   (Float(1.0f) + simd::max(simd::max(simd::abs(p.x), simd::abs(p.y)), simd::abs(p.z)));
    Vec3P shadowOrigin = p + n * offset;

    Float diffuse = ka * Float(frame.ambient);
    Float specular(0.0f);
    for (const LightSample& light : frame.lights) {
        Vec3P toLight(light.toLight);
        Float nDotL = dot(n, toLight);
        Mask lit = hitLanes & (nDotL > Float(0.0f));
        if (simd::none(lit)) continue;
        counts.shadow += std::uint64_t(__builtin_popcount(simd::bits(lit)));
        lit = simd::andNot(lit, frame.bvh.occluded(ParallelRays(shadowOrigin, light.toLight), lit, Float(0.0f),
                                                    Float(kInfinity), skip));
        if (simd::none(lit)) continue;
        Float intensity(light.intensity);
        diffuse = simd::select(lit, diffuse + intensity * kd * nDotL, diffuse);
        Vec3P reflected = n * (Float(2.0f) * nDotL) - toLight;
        Float rDotV = dot(reflected, toEye);
        Mask shiny = lit & (rDotV > Float(0.0f)) & (ks > Float(0.0f));
        if (simd::any(shiny))
            specular = simd::select(shiny, specular + intensity * ks * simd::powPositive(rDotV, shininess), specular);
    }
    out.r = simd::select(hitLanes, color.x * diffuse + specular, out.r);
    out.g = simd::select(hitLanes, color.y * diffuse + specular, out.g);
    out.b = simd::select(hitLanes, color.z * diffuse + specular, out.b);
    return out;
}

/// Lane version of toByte(): floor(255 * clamp(v) + 0.5), NaN -> 0.
inline Int toBytes(Float v) {
    v = simd::min(simd::max(v, Float(0.0f)), Float(1.0f));
    return simd::truncateToInt(simd::floor(Float(255.0f) * v + Float(0.5f)));
}

}  // namespace f2
