#include "core/geometry/primitive.h"

#include <algorithm>
#include <cmath>

namespace f2 {

Bounds primitiveBounds(const Primitive& prim) {
    Vec3 extent;
    switch (prim.kind) {
        case ShapeKind::Sphere:
            extent = prim.half;
            break;
        case ShapeKind::Cylinder: {
            // A disc of radius r perpendicular to axis a spans r*sqrt(1 - a_i^2) along world axis i.
            Vec3 a = prim.axes[1];
            float r = prim.half.x, h = prim.half.y;
            for (int i = 0; i < 3; ++i)
                extent[i] = std::fabs(a[i]) * h + r * std::sqrt(std::max(0.0f, 1.0f - a[i] * a[i]));
            break;
        }
        case ShapeKind::Box:
            for (int i = 0; i < 3; ++i)
                extent[i] = std::fabs(prim.axes[0][i]) * prim.half.x +
                            std::fabs(prim.axes[1][i]) * prim.half.y +
                            std::fabs(prim.axes[2][i]) * prim.half.z;
            break;
    }
    // A hair of padding so rounding never clips a surface out of its box, also
    // for a tiny object far from the origin where float spacing is coarse.
    Vec3 c = vabs(prim.centre);
    float pad = std::max(std::max(c.x, c.y), c.z) * 1e-6f + 1e-6f;
    extent = extent * 1.0001f + Vec3{pad, pad, pad};
    return {prim.centre - extent, prim.centre + extent};
}

}  // namespace f2
