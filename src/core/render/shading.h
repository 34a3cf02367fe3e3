#pragma once
/// Phong shading with one shadow ray per directional light (SPEC 3).
#include <algorithm>
#include <cmath>

#include "core/render/frame_scene.h"

namespace f2 {

/// Shadow rays start this far off the surface, relative to the hit point's
/// magnitude, so a surface never shadows itself (float spacing grows with it).
inline constexpr float kShadowBias = 5e-5f;

inline float shadowOffset(Vec3 p) {
    Vec3 a = vabs(p);
    return kShadowBias * (1.0f + std::max(std::max(a.x, a.y), a.z));
}

/// Primary rays ignore hits nearer than this: with the eye exactly on a
/// surface, roots at t ~ 0 would otherwise fall either side of 0 by rounding
/// and speckle the image; this way they consistently count as behind the eye.
inline float primaryRayStart(Vec3 eye) { return shadowOffset(eye); }

/// Colour (0..1, unclamped) of the nearest hit `hit` of `ray`.
inline Vec3 shadeHit(const FrameScene& frame, const Ray& ray, const HitRecord& hit) {
    const Primitive& prim = frame.primitives[hit.primitive];
    const Surface& surface = frame.surfaces[hit.primitive];
    const Material& m = surface.material;
    Vec3 p = ray.origin + ray.direction * hit.t;
    Vec3 n = primitiveNormal(prim, p, hit.face);
    bool inside = dot(n, ray.direction) > 0;  // seen from within the primitive
    if (inside) n = -n;                       // face the viewer
    // A shadow ray leaving a convex primitive's outside never meets it again,
    // so it skips that primitive; from the inside it must not.
    std::uint32_t skip = inside ? Bvh::kNoPrimitive : hit.primitive;
    Vec3 toEye = -ray.direction;
    Vec3 shadowOrigin = p + n * shadowOffset(p);

    float diffuse = m.ka * frame.ambient;
    float specular = 0;
    for (const LightSample& light : frame.lights) {
        float nDotL = dot(n, light.toLight);
        if (nDotL <= 0) continue;
        if (frame.bvh.occluded({shadowOrigin, light.toLight}, 0.0f, kInfinity, skip)) continue;
        diffuse += light.intensity * m.kd * nDotL;
        Vec3 reflected = n * (2 * nDotL) - light.toLight;
        float rDotV = dot(reflected, toEye);
        if (rDotV > 0 && m.ks > 0) specular += light.intensity * m.ks * std::pow(rDotV, m.n);
    }
    return surface.color * diffuse + Vec3{specular, specular, specular};
}

/// Colour of a primary ray from the eye: the shaded nearest hit or the background.
inline Vec3 traceRay(const FrameScene& frame, const Ray& ray) {
    HitRecord hit;
    if (!frame.bvh.intersect(ray, primaryRayStart(ray.origin), kInfinity, hit)) return frame.background;
    return shadeHit(frame, ray, hit);
}

/// floor(255 * clamp(v) + 0.5)
inline std::uint8_t toByte(float v) {
    v = std::clamp(v, 0.0f, 1.0f);  // NaN-safe: clamp keeps NaN, so test below
    return v == v ? std::uint8_t(std::floor(255.0f * v + 0.5f)) : 0;
}

}  // namespace f2
