#pragma once
/// Exact ray intersection with each primitive in its own local frame.
///
/// Cylinders and boxes are treated as intersections of slabs (and of an
/// infinite cylinder), so entry = max of the entries and exit = min of the
/// exits. That form has no cracks on cap rims or box edges: a ray that grazes
/// an edge hits one face or the other, never slips between them.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/geometry/primitive.h"

namespace f2 {

/// Which surface of a primitive a ray hit; decides the normal.
enum class Face : std::uint8_t { Curved, Cap, SlabX, SlabY, SlabZ };

struct Interval {
    float enter, exit;
    Face enterFace, exitFace;
};

namespace detail {

/// Roots of |perp + t*dperp|^2 = r^2 (perp, dperp: components orthogonal to an axis).
inline bool quadraticInterval(Vec3 perp, Vec3 dperp, float r, float& t0, float& t1) {
    float a = dot(dperp, dperp);
    float c = dot(perp, perp) - r * r;
    if (a <= 1e-20f) {  // moving parallel to the axis: inside for all t or never
        if (c > 0) return false;
        t0 = -kInfinity;
        t1 = kInfinity;
        return true;
    }
    float inverseA = 1.0f / a;
    float b = dot(perp, dperp);
    // Discriminant via the closest approach, which keeps precision when the
    // ray starts far from the primitive.
    Vec3 closest = perp - dperp * (b * inverseA);
    float disc = r * r - dot(closest, closest);
    if (disc < 0) return false;
    float s = std::sqrt(disc * a);
    t0 = (-b - s) * inverseA;
    t1 = (-b + s) * inverseA;
    return true;
}

/// The sphere's case of the above: ray directions are unit, so a = 1.
inline bool sphereInterval(Vec3 oc, Vec3 d, float r, float& t0, float& t1) {
    float b = dot(oc, d);
    Vec3 closest = oc - d * b;
    float disc = r * r - dot(closest, closest);
    if (disc < 0) return false;
    float s = std::sqrt(disc);
    t0 = -b - s;
    t1 = -b + s;
    return true;
}

/// Slab |o + t d| <= h along one local axis; narrows [enter, exit].
inline bool clipSlab(float o, float d, float h, Face face, Interval& iv) {
    if (d == 0.0f) return std::fabs(o) <= h;
    float inv = 1.0f / d;
    float tNear = (-h - o) * inv, tFar = (h - o) * inv;
    if (tNear > tFar) std::swap(tNear, tFar);
    if (tNear > iv.enter) {
        iv.enter = tNear;
        iv.enterFace = face;
    }
    if (tFar < iv.exit) {
        iv.exit = tFar;
        iv.exitFace = face;
    }
    return iv.enter <= iv.exit;
}

}  // namespace detail

/// The interval of t over which the (infinite) ray is inside the primitive.
inline bool primitiveInterval(const Primitive& prim, const Ray& ray, Interval& iv) {
    Vec3 oc = ray.origin - prim.centre;
    switch (prim.kind) {
        case ShapeKind::Sphere: {
            float t0, t1;
            if (!detail::sphereInterval(oc, ray.direction, prim.half.x, t0, t1)) return false;
            iv = {t0, t1, Face::Curved, Face::Curved};
            return true;
        }
        case ShapeKind::Cylinder: {
            Vec3 axis = prim.axes[1];
            float oa = dot(oc, axis), da = dot(ray.direction, axis);
            float t0, t1;
            if (!detail::quadraticInterval(oc - axis * oa, ray.direction - axis * da, prim.half.x, t0, t1))
                return false;
            iv = {t0, t1, Face::Curved, Face::Curved};
            return detail::clipSlab(oa, da, prim.half.y, Face::Cap, iv);
        }
        case ShapeKind::Box: {
            iv = {-kInfinity, kInfinity, Face::SlabX, Face::SlabX};
            for (int i = 0; i < 3; ++i) {
                if (!detail::clipSlab(dot(oc, prim.axes[i]), dot(ray.direction, prim.axes[i]), prim.half[i],
                                      Face(int(Face::SlabX) + i), iv))
                    return false;
            }
            return true;
        }
    }
    return false;
}

/// Nearest surface crossing within (tMin, tMax): the entry, or the exit when
/// the origin is inside. False when there is none.
inline bool intersectPrimitive(const Primitive& prim, const Ray& ray, float tMin, float tMax, float& tHit,
                               Face& face) {
    Interval iv;
    if (!primitiveInterval(prim, ray, iv)) return false;
    if (iv.enter > tMin) {
        if (iv.enter >= tMax) return false;
        tHit = iv.enter;
        face = iv.enterFace;
        return true;
    }
    if (iv.exit > tMin && iv.exit < tMax) {
        tHit = iv.exit;
        face = iv.exitFace;
        return true;
    }
    return false;
}

/// The smallest float above t (t >= 0; infinity stays): a bound that lets a
/// hit at exactly t through, for breaking ties between equal distances.
inline float nextUp(float t) {
    return t < kInfinity ? __builtin_bit_cast(float, __builtin_bit_cast(std::uint32_t, t) + 1u) : t;
}

/// Unit outward normal at world point `p` on surface `face` of the primitive.
inline Vec3 primitiveNormal(const Primitive& prim, Vec3 p, Face face) {
    Vec3 local = p - prim.centre;
    switch (face) {
        case Face::Curved:
            if (prim.kind == ShapeKind::Sphere) return normalize(local);
            return normalize(local - prim.axes[1] * dot(local, prim.axes[1]));
        case Face::Cap:
            return dot(local, prim.axes[1]) >= 0 ? prim.axes[1] : -prim.axes[1];
        default: {
            Vec3 axis = prim.axes[int(face) - int(Face::SlabX)];
            return dot(local, axis) >= 0 ? axis : -axis;
        }
    }
}

}  // namespace f2
