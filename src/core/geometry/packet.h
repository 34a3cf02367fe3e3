#pragma once
/// Ray packets: simd::kWidth rays traced together, one per lane. The
/// intersection code mirrors intersect.h operation for operation, so a lane
/// finds exactly the distance the single-ray path finds.
#include "core/geometry/intersect.h"
#include "core/simd/simd.h"

namespace f2 {

using simd::Float;
using simd::Int;
using simd::Mask;

/// A Vec3 per lane.
struct Vec3P {
    Float x, y, z;
    Vec3P() = default;
    Vec3P(Float x_, Float y_, Float z_) : x(x_), y(y_), z(z_) {}
    explicit Vec3P(Vec3 v) : x(v.x), y(v.y), z(v.z) {}
};
inline Vec3P operator+(const Vec3P& a, const Vec3P& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3P operator-(const Vec3P& a, const Vec3P& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3P operator*(const Vec3P& a, Float s) { return {a.x * s, a.y * s, a.z * s}; }
inline Vec3P operator-(const Vec3P& a) { return {-a.x, -a.y, -a.z}; }
inline Float dot(const Vec3P& a, const Vec3P& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3P select(Mask m, const Vec3P& a, const Vec3P& b) {
    return {simd::select(m, a.x, b.x), simd::select(m, a.y, b.y), simd::select(m, a.z, b.z)};
}

struct RayPacket {
    Vec3P origin, direction, inverseDirection;

    RayPacket(const Vec3P& o, const Vec3P& d)
        : origin(o), direction(d), inverseDirection(Float(1.0f) / d.x, Float(1.0f) / d.y, Float(1.0f) / d.z) {}
};

/// Nearest hits of a packet; `t` starts as tMax.
struct PacketHit {
    Float t{kInfinity};
    Int primitive{0};  ///< in leaf order: an index into Bvh::orderedPrimitives(), not the frame's
    Int face{0};
};

namespace detail {

/// Lane version of quadraticInterval() in intersect.h.
inline Mask quadraticIntervalP(const Vec3P& perp, const Vec3P& dperp, Float r, Float& t0, Float& t1) {
    Float a = dot(dperp, dperp);
    Float c = dot(perp, perp) - r * r;
    Mask parallel = a <= Float(1e-20f);
    Float inverseA = Float(1.0f) / a;
    Float b = dot(perp, dperp);
    Vec3P closest = perp - dperp * (b * inverseA);
    Float disc = r * r - dot(closest, closest);
    Float s = simd::sqrt(disc * a);
    t0 = simd::select(parallel, Float(-kInfinity), (-b - s) * inverseA);
    t1 = simd::select(parallel, Float(kInfinity), (-b + s) * inverseA);
    // Parallel to the axis: inside for all t or never; otherwise real roots.
    return (parallel & (c <= Float(0.0f))) | simd::andNot(disc >= Float(0.0f), parallel);
}

/// Lane version of sphereInterval().
inline Mask sphereIntervalP(const Vec3P& oc, const Vec3P& d, Float r, Float& t0, Float& t1) {
    Float b = dot(oc, d);
    Vec3P closest = oc - d * b;
    Float disc = r * r - dot(closest, closest);
    Float s = simd::sqrt(disc);
    t0 = -b - s;
    t1 = -b + s;
    return disc >= Float(0.0f);
}

/// Lane version of clipSlab(): narrows [enter, exit] by |o + t d| <= h.
inline Mask clipSlabP(Float o, Float d, Float inv, Float h, Face face, Float& enter, Float& exit, Int& enterFace,
                      Int& exitFace) {
    Mask flat = d == Float(0.0f);
    Float a = (-h - o) * inv, b = (h - o) * inv;
    Mask swapped = a > b;
    Float tNear = simd::select(swapped, b, a), tFar = simd::select(swapped, a, b);
    Mask nearer = simd::andNot(tNear > enter, flat);
    Mask farther = simd::andNot(tFar < exit, flat);
    enter = simd::select(nearer, tNear, enter);
    enterFace = simd::select(nearer, Int(int(face)), enterFace);
    exit = simd::select(farther, tFar, exit);
    exitFace = simd::select(farther, Int(int(face)), exitFace);
    return (flat & (simd::abs(o) <= h)) | simd::andNot(enter <= exit, flat);
}

}  // namespace detail

/// Lane version of primitiveInterval(): where each ray is inside the primitive.
/// Forced inline: as a call it made the traversal loops spill and reload their
/// packet registers around every primitive test (robots:10000 +1 to 1.6 %).
[[gnu::always_inline]] inline Mask primitiveIntervalP(const Primitive& prim, const RayPacket& ray, Float& enter,
                                                     Float& exit, Int& enterFace, Int& exitFace) {
    Vec3P oc = ray.origin - Vec3P(prim.centre);
    switch (prim.kind) {
        case ShapeKind::Sphere:
            enterFace = exitFace = Int(int(Face::Curved));
            return detail::sphereIntervalP(oc, ray.direction, Float(prim.half.x), enter, exit);
        case ShapeKind::Cylinder: {
            Vec3P axis(prim.axes[1]);
            Float oa = dot(oc, axis), da = dot(ray.direction, axis);
            Mask valid = detail::quadraticIntervalP(oc - axis * oa, ray.direction - axis * da, Float(prim.half.x),
                                                    enter, exit);
            enterFace = exitFace = Int(int(Face::Curved));
            return valid & detail::clipSlabP(oa, da, Float(1.0f) / da, Float(prim.half.y), Face::Cap, enter, exit,
                                             enterFace, exitFace);
        }
        case ShapeKind::Box: {
            enter = Float(-kInfinity);
            exit = Float(kInfinity);
            enterFace = exitFace = Int(int(Face::SlabX));
            Mask valid = simd::allLanes();
            if (prim.axisAligned) {
                // Local axes are the world axes: the packet's reciprocals serve as they are.
                const Float* o[3] = {&oc.x, &oc.y, &oc.z};
                const Float* d[3] = {&ray.direction.x, &ray.direction.y, &ray.direction.z};
                const Float* inv[3] = {&ray.inverseDirection.x, &ray.inverseDirection.y, &ray.inverseDirection.z};
                for (int i = 0; i < 3; ++i)
                    valid = valid & detail::clipSlabP(*o[i], *d[i], *inv[i], Float(prim.half[i]),
                                                      Face(int(Face::SlabX) + i), enter, exit, enterFace, exitFace);
                return valid;
            }
            for (int i = 0; i < 3; ++i) {
                Vec3P axis(prim.axes[i]);
                Float d = dot(ray.direction, axis);
                valid = valid & detail::clipSlabP(dot(oc, axis), d, Float(1.0f) / d, Float(prim.half[i]),
                                                  Face(int(Face::SlabX) + i), enter, exit, enterFace, exitFace);
            }
            return valid;
        }
    }
    return simd::noLanes();
}

/// Lanes of `active` whose nearest crossing of the primitive lies in (tMin, tMax);
/// writes that distance and face into those lanes of tHit and face.
inline Mask intersectPrimitiveP(const Primitive& prim, const RayPacket& ray, Mask active, Float tMin, Float tMax,
                                Float& tHit, Int& face) {
    Float enter(0.0f), exit(0.0f);  // initialised: GCC cannot see every kind sets them
    Int enterFace(0), exitFace(0);
    Mask valid = primitiveIntervalP(prim, ray, enter, exit, enterFace, exitFace) & active;
    if (simd::none(valid)) return valid;
    Mask fromOutside = enter > tMin;
    Float t = simd::select(fromOutside, enter, exit);
    Mask hit = valid & (t > tMin) & (t < tMax);
    tHit = simd::select(hit, t, tHit);
    face = simd::select(hit, simd::select(fromOutside, enterFace, exitFace), face);
    return hit;
}

/// Lane version of primitiveNormal(): unit outward normal at p on `face`.
inline Vec3P primitiveNormalP(const Primitive& prim, const Vec3P& p, Int face) {
    Vec3P local = p - Vec3P(prim.centre);
    auto normalized = [](const Vec3P& v) { return v * (Float(1.0f) / simd::sqrt(dot(v, v))); };
    auto outward = [&](Vec3 axis) {
        Vec3P a(axis);
        return select(dot(local, a) >= Float(0.0f), a, -a);
    };
    switch (prim.kind) {
        case ShapeKind::Sphere: return normalized(local);
        case ShapeKind::Cylinder: {
            Vec3P axis(prim.axes[1]);
            Vec3P side = normalized(local - axis * dot(local, axis));
            return select(face == Int(int(Face::Cap)), outward(prim.axes[1]), side);
        }
        case ShapeKind::Box: {
            Vec3P n = outward(prim.axes[2]);
            n = select(face == Int(int(Face::SlabY)), outward(prim.axes[1]), n);
            return select(face == Int(int(Face::SlabX)), outward(prim.axes[0]), n);
        }
    }
    return local;
}

}  // namespace f2
