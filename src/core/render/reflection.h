#pragma once
/// Mirror reflection (docs/rendering.md), as POV-Ray's `finish { reflection r }`:
/// a surface adds r times the colour its mirrored ray sees, rays reflected
/// again up to kMaxTraceLevel; and the whole colour of a primary ray.
#include <cmath>

#include "core/render/shading.h"

namespace f2 {

/// Levels of rays traced, as POV-Ray's default max_trace_level: the primary
/// ray is level 1 and each reflection one more, so a hit on level 5 reflects
/// nothing (POV-Ray's black beyond the last level adds nothing either).
inline constexpr int kMaxTraceLevel = 5;

/// The mirror image of the unit direction `d` about the unit normal `n`, unit.
inline Vec3 reflectedDirection(Vec3 d, Vec3 n) {
    Vec3 r = d - n * (2.0f * dot(d, n));
    return r * (1.0f / std::sqrt(dot(r, r)));
}

/// The ray a mirror sends from hit `s` of a ray along `direction`: from where
/// shadow rays start, skipping the same primitive (from outside a convex
/// primitive the mirrored ray leaves it for good).
inline Ray mirroredRay(const ShadingPoint& s, Vec3 direction) {
    return {s.shadowOrigin, reflectedDirection(direction, s.normal)};
}

/// Colour (0..1, unclamped) of hit `hit` of a ray on trace level `level`:
/// its own shading plus, on a mirror, r times what its mirrored ray sees
/// (the background when that ray escapes).
inline Vec3 shadeWithReflections(const PreparedFrame& frame, const Ray& ray, const HitRecord& hit,
                                 int level) {
    const Vec3 local = shadeHit(frame, ray, hit);
    const float r = frame.surfaces[hit.primitive].material.reflection;
    if (!(r > 0.0f) || level >= kMaxTraceLevel) return local;
    const ShadingPoint s = shadingPoint(frame, ray, hit);
    const Ray mirrored = mirroredRay(s, ray.direction);
    HitRecord next;
    const Vec3 seen = frame.bvh.intersect(mirrored, 0.0f, kInfinity, next, s.skip)
                          ? shadeWithReflections(frame, mirrored, next, level + 1)
                          : frame.background;
    return local + seen * r;
}

/// Colour of a primary ray from the eye: the shaded nearest hit (with its
/// reflections) or the background.
inline Vec3 traceRay(const PreparedFrame& frame, const Ray& ray) {
    HitRecord hit;
    if (!frame.bvh.intersect(ray, primaryRayStart(ray.origin), kInfinity, hit)) return frame.background;
    return shadeWithReflections(frame, ray, hit, 1);
}

}  // namespace f2
