#pragma once
/// Lane version of reflection.h: the mirrored rays of a packet traced level by
/// level, and the colours folded back in the order shadeWithReflections()
/// adds them, so each lane gets the reference path's bits. Private to the
/// core (SIMD types).
#include "core/render/packet_shading.h"
#include "core/render/reflection.h"

namespace f2 {

/// Lane version of reflectedDirection().
inline Vec3P reflectedDirectionP(const Vec3P& d, const Vec3P& n) {
    Vec3P r = d - n * (Float(2.0f) * dot(d, n));
    return r * (Float(1.0f) / simd::sqrt(dot(r, r)));
}

/// The surfaces that the mirrored rays of `s` (from its `active` lanes) meet.
inline PacketSurface findMirroredSurfaces(const PreparedFrame& frame, const PacketSurface& s, Mask active,
                                          RayCounts& counts) {
    counts.reflected += std::uint64_t(__builtin_popcount(simd::bits(active)));
    const FreeRays rays(s.shadowOrigin, reflectedDirectionP(-s.toEye, s.normal));
    PacketHit hit;
    intersectPacket(frame.bvh, rays, active, Float(0.0f), hit, s.skip);
    return surfacesAt(frame, rays, hit, active);
}

/// The colours of a packet's surfaces `s` (their own shading `local`, from
/// shadeSurfaces()) with what their mirrors reflect, to kMaxTraceLevel.
inline ColorP withReflections(const PreparedFrame& frame, const PacketSurface& s, const ColorP& local,
                              RayCounts& counts) {
    Mask mirrors = s.hitLanes & (s.reflection > Float(0.0f));
    if (simd::none(mirrors)) return local;
    // Level k + 1 is the primary ray's k-th reflection; reflects[k]: its lanes that reflect further.
    ColorP seen[kMaxTraceLevel];
    Mask reflects[kMaxTraceLevel];
    Float weight[kMaxTraceLevel];
    seen[0] = local;
    reflects[0] = mirrors;
    weight[0] = s.reflection;
    PacketSurface at = s;
    int levels = 1;
    for (; levels < kMaxTraceLevel && simd::any(reflects[levels - 1]); ++levels) {
        at = findMirroredSurfaces(frame, at, reflects[levels - 1], counts);
        // Shadow rays from here start at the root: the tile's entry nodes are for its primary hits.
        seen[levels] = shadeSurfaces(frame, at, {}, counts);
        reflects[levels] = at.hitLanes & (at.reflection > Float(0.0f));
        weight[levels] = at.reflection;
    }
    // Innermost first, as the recursion of shadeWithReflections() returns: local + seen * r.
    ColorP c = seen[levels - 1];
    for (int k = levels - 2; k >= 0; --k) {
        const ColorP& own = seen[k];
        c = {simd::select(reflects[k], own.r + c.r * weight[k], own.r),
             simd::select(reflects[k], own.g + c.g * weight[k], own.g),
             simd::select(reflects[k], own.b + c.b * weight[k], own.b)};
    }
    return c;
}

}  // namespace f2
