#pragma once
/// The checker pattern of `/checker` (docs/rendering.md): POV-Ray's
/// `pigment { checker C1 C2 scale s }` in the primitive's own frame, so the
/// pattern moves and turns with the object.
#include <cmath>

#include "core/anim/evaluated_frame.h"

namespace f2 {

/// 0 or 1: the parity of the cell that holds `c` along one axis, floor(c) mod 2.
/// Exact for |c| < 2^24; beyond, every float is an even whole number (0).
inline float cellParity(float c) {
    const float cell = std::floor(c);
    return cell - 2.0f * std::floor(cell * 0.5f);
}

/// The colour of `surface` at the world point `position` of `prim`, whose
/// outward unit normal there is `outward`. The pattern is read `inset` inside
/// the surface (the shadow offset): a face that lies exactly on a plane
/// between cells then takes one cell throughout instead of speckling.
inline Vec3 surfaceColorAt(const Surface& surface, const Primitive& prim, Vec3 position, Vec3 outward,
                           float inset) {
    if (!(surface.checkerSize > 0.0f)) return surface.color;
    const Vec3 local = position - outward * inset - prim.centre;
    // Cells of side s in the primitive's frame: (floor(x/s) + floor(y/s) + floor(z/s)) mod 2.
    const float parity = cellParity(dot(prim.axes[0], local) / surface.checkerSize) +
                         cellParity(dot(prim.axes[1], local) / surface.checkerSize) +
                         cellParity(dot(prim.axes[2], local) / surface.checkerSize);
    return parity == 1.0f || parity == 3.0f ? surface.checkerColor : surface.color;
}

}  // namespace f2
