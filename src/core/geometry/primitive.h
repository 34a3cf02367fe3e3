#pragma once
/// World-space primitives of one evaluated frame: a sphere, closed cylinder or
/// box placed by a rigid transform, and its bounds.
#include <cstdint>
#include <limits>

#include "core/geometry/shape_kind.h"
#include "core/math/transform.h"

namespace f2 {

/// A ray with a unit direction; t counts distance along it.
struct Ray {
    Vec3 origin;
    Vec3 direction;
};

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

/// Intersection data of a primitive. `axes` are the rows of localFromWorld:
/// local coordinate i of a world point p is dot(axes[i], p - centre).
/// One cache line each, on a line boundary.
struct alignas(64) Primitive {
    Vec3 centre;
    Vec3 axes[3];
    /// Sphere: (r, -, -); cylinder: (r, h/2, -); box: half sides.
    Vec3 half;
    ShapeKind kind;
    bool axisAligned = false;  ///< axes are exactly the world axes (fast box test)
};
static_assert(sizeof(Primitive) == 64);

/// Axis-aligned world bounds.
struct Bounds {
    Vec3 lo{kInfinity, kInfinity, kInfinity};
    Vec3 hi{-kInfinity, -kInfinity, -kInfinity};

    void grow(const Bounds& b) {
        lo = vmin(lo, b.lo);
        hi = vmax(hi, b.hi);
    }
    void grow(Vec3 p) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    Vec3 centroid() const { return lo * 0.5f + hi * 0.5f; }  // no overflow near the float limit
    float halfArea() const {
        Vec3 e = hi - lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

/// A convex region bounded by planes, dot(normal, p) + offset >= 0 inside:
/// the pyramid of one tile's primary rays.
struct Frustum {
    Vec3 normal[4];
    float offset[4];
    /// True when no point of the box is inside (tested against each plane alone: conservative).
    bool excludes(const Bounds& b) const {
        for (int i = 0; i < 4; ++i) {
            Vec3 n = normal[i];
            Vec3 far{n.x >= 0 ? b.hi.x : b.lo.x, n.y >= 0 ? b.hi.y : b.lo.y, n.z >= 0 ? b.hi.z : b.lo.z};
            if (dot(n, far) + offset[i] < 0) return true;
        }
        return false;
    }
};

Bounds primitiveBounds(const Primitive& prim);

/// Builds a primitive from its kind, SceneObject-style size and world transform.
/// Inline: built in place in the frame's array (a returned copy stalls on store forwarding).
inline Primitive makePrimitive(ShapeKind kind, Vec3 size, const Transform& worldFromLocal) {
    Primitive p;
    p.kind = kind;
    p.centre = worldFromLocal.translation;
    // Rows of localFromWorld are the columns of worldFromLocal.
    for (int i = 0; i < 3; ++i) p.axes[i] = worldFromLocal.linear.column(i);
    p.axisAligned = p.axes[0] == Vec3{1, 0, 0} && p.axes[1] == Vec3{0, 1, 0} && p.axes[2] == Vec3{0, 0, 1};
    switch (kind) {
        case ShapeKind::Sphere:
            p.half = {size.x, size.x, size.x};
            break;
        case ShapeKind::Cylinder:
            p.half = {size.x, size.y * 0.5f, size.x};
            break;
        case ShapeKind::Box:
            p.half = size * 0.5f;
            break;
    }
    return p;
}

}  // namespace f2
