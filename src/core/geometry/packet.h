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

// Mixed forms: a Vec3 shared by every lane meets a Vec3P. Each broadcasts the
// shared value and then does the lane operation, so the bits are the same.
inline Vec3P operator+(Vec3 a, const Vec3P& b) { return Vec3P(a) + b; }
inline Vec3P operator+(const Vec3P& a, Vec3 b) { return a + Vec3P(b); }
inline Vec3P operator-(Vec3 a, const Vec3P& b) { return Vec3P(a) - b; }
inline Vec3P operator-(const Vec3P& a, Vec3 b) { return a - Vec3P(b); }
inline Vec3P operator*(Vec3 a, Float s) { return Vec3P(a) * s; }
inline Float dot(const Vec3P& a, Vec3 b) { return dot(a, Vec3P(b)); }
inline Float dot(Vec3 a, const Vec3P& b) { return dot(Vec3P(a), b); }

inline Vec3P vmin(const Vec3P& a, const Vec3P& b) {
    return {simd::min(a.x, b.x), simd::min(a.y, b.y), simd::min(a.z, b.z)};
}
inline Vec3P vmax(const Vec3P& a, const Vec3P& b) {
    return {simd::max(a.x, b.x), simd::max(a.y, b.y), simd::max(a.z, b.z)};
}

inline Float component(const Vec3P& v, int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); }
inline float component(Vec3 v, int axis) { return v[axis]; }
inline float laneOf(float shared, int) { return shared; }
inline float laneOf(Float v, int lane) { return simd::lane(v, lane); }
/// Every lane or none, for a condition on a value the lanes share.
inline Mask lanesWhere(bool all) { return all ? simd::allLanes() : simd::noLanes(); }
inline Mask lanesWhere(Mask m) { return m; }

inline Vec3 reciprocal(Vec3 d) { return {1.0f / d.x, 1.0f / d.y, 1.0f / d.z}; }
inline Vec3P reciprocal(const Vec3P& d) { return {Float(1.0f) / d.x, Float(1.0f) / d.y, Float(1.0f) / d.z}; }

/// simd::kWidth rays traced together, one per lane. Origin and Direction are
/// each Vec3P (one per lane) or Vec3 (one for the whole packet): primary rays
/// share the eye and shadow rays share the light's direction, and whatever
/// depends only on a shared value is then worked out once per box or
/// primitive instead of in every lane, with the same result.
template <class Origin, class Direction>
struct Rays {
    Origin origin;
    Direction direction, inverseDirection;

    Rays(const Origin& o, const Direction& d) : origin(o), direction(d), inverseDirection(reciprocal(d)) {}
};
using EyeRays = Rays<Vec3, Vec3P>;       ///< primary rays: every lane leaves the eye
using ParallelRays = Rays<Vec3P, Vec3>;  ///< shadow rays toward a directional light
using FreeRays = Rays<Vec3P, Vec3P>;     ///< rays that share neither origin nor direction

/// Nearest hits of a packet; `t` starts as tMax.
struct PacketHit {
    Float t{kInfinity};
    Int primitive{0};   ///< in leaf order: an index into Bvh::orderedPrimitives(), not the frame's
    Int frameIndex{0};  ///< the frame's index of the same primitive: the lower one wins a tie
    Int face{0};
};

/// Lane version of nextUp() in intersect.h.
inline Float nextUp(Float t) {
    return simd::select(t < Float(kInfinity), simd::fromBits(simd::bitsOf(t) + Int(1)), t);
}

namespace detail {

/// Lane version of quadraticInterval() in intersect.h.
template <class Perp, class DPerp>
inline Mask quadraticIntervalP(const Perp& perp, const DPerp& dperp, float r, Float& t0, Float& t1) {
    auto a = dot(dperp, dperp);
    auto c = dot(perp, perp) - r * r;
    Mask parallel = lanesWhere(a <= decltype(a)(1e-20f));
    auto inverseA = decltype(a)(1.0f) / a;
    Float b = dot(perp, dperp);
    Vec3P closest = perp - dperp * (b * inverseA);
    Float disc = r * r - dot(closest, closest);
    Float s = simd::sqrt(disc * a);
    t0 = simd::select(parallel, Float(-kInfinity), (-b - s) * inverseA);
    t1 = simd::select(parallel, Float(kInfinity), (-b + s) * inverseA);
    // Parallel to the axis: inside for all t or never; otherwise real roots.
    return (parallel & lanesWhere(c <= decltype(c)(0.0f))) | simd::andNot(disc >= Float(0.0f), parallel);
}

/// Lane version of sphereInterval().
template <class Origin, class Direction>
inline Mask sphereIntervalP(const Origin& oc, const Direction& d, float r, Float& t0, Float& t1) {
    Float b = dot(oc, d);
    Vec3P closest = oc - d * b;
    Float disc = r * r - dot(closest, closest);
    Float s = simd::sqrt(disc);
    t0 = -b - s;
    t1 = -b + s;
    return disc >= Float(0.0f);
}

/// Lane version of clipSlab(): narrows [enter, exit] by |o + t d| <= h.
template <class O, class D>
inline Mask clipSlabP(O o, D d, D inv, float h, Face face, Float& enter, Float& exit, Int& enterFace,
                      Int& exitFace) {
    Mask flat = lanesWhere(d == D(0.0f));
    Float a = (-h - o) * inv, b = (h - o) * inv;
    Mask swapped = a > b;
    Float tNear = simd::select(swapped, b, a), tFar = simd::select(swapped, a, b);
    Mask nearer = simd::andNot(tNear > enter, flat);
    Mask farther = simd::andNot(tFar < exit, flat);
    enter = simd::select(nearer, tNear, enter);
    enterFace = simd::select(nearer, Int(int(face)), enterFace);
    exit = simd::select(farther, tFar, exit);
    exitFace = simd::select(farther, Int(int(face)), exitFace);
    return (flat & (simd::abs(Float(o)) <= Float(h))) | simd::andNot(enter <= exit, flat);
}

}  // namespace detail

/// Lane version of primitiveInterval(): where each ray is inside the primitive.
/// Forced inline: as a call it made the traversal loops spill and reload their
/// packet registers around every primitive test (robots:10000 +1 to 1.6 %).
template <class Origin, class Direction>
[[gnu::always_inline]] inline Mask primitiveIntervalP(const Primitive& prim,
                                                      const Rays<Origin, Direction>& ray, Float& enter,
                                                      Float& exit, Int& enterFace, Int& exitFace) {
    auto oc = ray.origin - prim.centre;
    switch (prim.kind) {
        case ShapeKind::Sphere:
            enterFace = exitFace = Int(int(Face::Curved));
            return detail::sphereIntervalP(oc, ray.direction, prim.half.x, enter, exit);
        case ShapeKind::Cylinder: {
            Vec3 axis = prim.axes[1];
            auto oa = dot(oc, axis);
            auto da = dot(ray.direction, axis);
            Mask valid = detail::quadraticIntervalP(oc - axis * oa, ray.direction - axis * da, prim.half.x,
                                                    enter, exit);
            enterFace = exitFace = Int(int(Face::Curved));
            return valid & detail::clipSlabP(oa, da, decltype(da)(1.0f) / da, prim.half.y, Face::Cap, enter,
                                             exit, enterFace, exitFace);
        }
        case ShapeKind::Box: {
            enter = Float(-kInfinity);
            exit = Float(kInfinity);
            enterFace = exitFace = Int(int(Face::SlabX));
            Mask valid = simd::allLanes();
            if (prim.axisAligned) {
                // Local axes are the world axes: the packet's reciprocals serve as they are.
                for (int i = 0; i < 3; ++i)
                    valid = valid & detail::clipSlabP(component(oc, i), component(ray.direction, i),
                                                      component(ray.inverseDirection, i), prim.half[i],
                                                      Face(int(Face::SlabX) + i), enter, exit, enterFace,
                                                      exitFace);
                return valid;
            }
            for (int i = 0; i < 3; ++i) {
                Vec3 axis = prim.axes[i];
                auto d = dot(ray.direction, axis);
                valid =
                    valid & detail::clipSlabP(dot(oc, axis), d, decltype(d)(1.0f) / d, prim.half[i],
                                              Face(int(Face::SlabX) + i), enter, exit, enterFace, exitFace);
            }
            return valid;
        }
    }
    return simd::noLanes();
}

/// Lanes of `active` whose nearest crossing of the primitive lies in (tMin, tMax);
/// writes that distance and face into those lanes of tHit and face. Forced
/// inline as well: the any-hit loop had kept it as a call (robots:10000 +4 %).
template <class Origin, class Direction>
[[gnu::always_inline]] inline Mask intersectPrimitiveP(const Primitive& prim,
                                                       const Rays<Origin, Direction>& ray, Mask active,
                                                       Float tMin, Float tMax, Float& tHit, Int& face) {
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
        case ShapeKind::Sphere:
            return normalized(local);
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
