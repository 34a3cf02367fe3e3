#pragma once
/// Lane version of checker.h, the same operations in the same order. Private
/// to the core (SIMD types).
#include "core/geometry/packet.h"
#include "core/render/checker.h"

namespace f2 {

/// Lane version of cellParity().
inline Float cellParityP(Float c) {
    const Float cell = simd::floor(c);
    return cell - Float(2.0f) * simd::floor(cell * Float(0.5f));
}

/// Lane version of surfaceColorAt(), for lanes that all hit `prim`.
inline Vec3P surfaceColorAtP(const Surface& surface, const Primitive& prim, const Vec3P& position,
                             const Vec3P& outward, Float inset) {
    if (!(surface.checkerSize > 0.0f)) return Vec3P(surface.color);
    const Vec3P local = position - outward * inset - prim.centre;
    const Float size(surface.checkerSize);
    const Float parity = cellParityP(dot(prim.axes[0], local) / size) +
                         cellParityP(dot(prim.axes[1], local) / size) +
                         cellParityP(dot(prim.axes[2], local) / size);
    const Mask odd = (parity == Float(1.0f)) | (parity == Float(3.0f));
    return select(odd, Vec3P(surface.checkerColor), Vec3P(surface.color));
}

}  // namespace f2
