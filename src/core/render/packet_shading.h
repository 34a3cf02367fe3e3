#pragma once
/// Phong shading of a whole packet (SPEC 3), the lane version of shading.h:
/// the same operations in the same order, except that pow() is the lane
/// approximation of simd_math.h (within 1e-6 relative). Private to the core
/// (SIMD types).
#include "core/geometry/bvh_packet.h"
#include "core/render/packet_beam.h"
#include "core/render/packet_checker.h"
#include "core/render/packet_light_sampling.h"
#include "core/render/prepared_frame.h"
#include "core/render/ray_counts.h"
#include "core/render/shading.h"
#include "core/simd/simd_math.h"

namespace f2 {

struct ColorP {
    Float r, g, b;
};

/// What the primary rays of a packet found: everything shading needs.
struct PacketSurface {
    Mask hitLanes;
    Vec3P normal;        ///< unit, facing the viewer
    Vec3P toEye;         ///< -ray direction
    Vec3P shadowOrigin;  ///< the hit point lifted off the surface (kShadowBias)
    Vec3P color;
    Float unlit;  ///< unlitSum(): ka · ambient + emission, worked out once per primitive
    Float kd, ks, shininess;
    Float reflection;  ///< Material::reflection
    Int skip;          ///< primitive (leaf order) the lane's shadow rays skip; -1 when seen from inside
};

/// The surfaces that `rays` met at `hit` in the `active` lanes (shadingPoint()
/// and the surface's values, lane by lane).
template <class Origin>
inline PacketSurface surfacesAt(const PreparedFrame& frame, const Rays<Origin, Vec3P>& rays,
                                const PacketHit& hit, Mask active) {
    PacketSurface s;
    s.hitLanes = active & (hit.t < Float(kInfinity));
    if (simd::none(s.hitLanes)) return s;

    // Gather each lane's surface: loop over the distinct primitives hit (few in a
    // coherent packet), filling their lanes from broadcast values. Hits name
    // primitives in the BVH's leaf order, whose copy is still in cache.
    const std::span<const Primitive> leafPrimitives = frame.bvh.orderedPrimitives();
    const std::span<const std::uint32_t> frameIndex = frame.bvh.originalIndices();
    Vec3P p = rays.origin + rays.direction * hit.t;
    // Where shadow rays start, and how far inside a checker pattern is read.
    Float offset = Float(kShadowBias) *
                   (Float(1.0f) + simd::max(simd::max(simd::abs(p.x), simd::abs(p.y)), simd::abs(p.z)));
    Vec3P n;
    alignas(64) std::int32_t primIds[simd::kWidth];
    simd::store(primIds, hit.primitive);
    for (Mask todo = s.hitLanes; simd::any(todo);) {
        std::int32_t id = primIds[simd::firstLane(todo)];
        Mask same = todo & (hit.primitive == Int(id));
        todo = simd::andNot(todo, same);
        const Surface& surface = frame.surfaces[frameIndex[std::size_t(id)]];
        const Primitive& prim = leafPrimitives[std::size_t(id)];
        n = select(same, primitiveNormalP(prim, p, hit.face), n);
        s.color = select(same, surfaceColorAtP(surface, prim, p, n, offset), s.color);
        s.unlit = simd::select(same, Float(unlitSum(surface.material, frame.ambient)), s.unlit);
        s.kd = simd::select(same, Float(surface.material.kd), s.kd);
        s.ks = simd::select(same, Float(surface.material.ks), s.ks);
        s.shininess = simd::select(same, Float(surface.material.n), s.shininess);
        s.reflection = simd::select(same, Float(surface.material.reflection), s.reflection);
    }
    Mask inside = dot(n, rays.direction) > Float(0.0f);  // seen from within the primitive
    s.normal = select(inside, -n, n);                    // face the viewer
    // As in shadeHit(): shadow rays skip their own primitive only from its outside.
    s.skip = simd::select(inside, Int(-1), hit.primitive);
    s.toEye = -rays.direction;
    s.shadowOrigin = p + s.normal * offset;
    return s;
}

/// Nearest surfaces of the `active` lanes of a packet of primary rays, found
/// in the subtrees of `entry` and then of `cell`: for rays that all lie inside
/// one frustum, its Bvh::entryNodes() (and no `cell`); in a frame binned by
/// PrimaryBins, its everywhere() and the packet's cell().
inline PacketSurface findSurfaces(const PreparedFrame& frame, const EyeRays& rays, Mask active,
                                  std::span<const std::uint32_t> entry, std::span<const std::uint32_t> cell,
                                  RayCounts& counts) {
    counts.primary += std::uint64_t(__builtin_popcount(simd::bits(active)));
    PacketHit hit;
    const Float tMin(primaryRayStart(rays.origin));
    if (cell.empty())
        intersectPacket(frame.bvh, rays, active, tMin, hit, entry);
    else
        intersectPacket(frame.bvh, rays, active, tMin, hit, entry, cell);
    return surfacesAt(frame, rays, hit, active);
}

/// addPhong() for the `lit` lanes, each with its own light direction and the
/// intensity that reaches it.
inline void addPhongP(const PacketSurface& s, const Vec3P& toLight, Float nDotL, Float intensity, Mask lit,
                      Float& diffuse, Float& specular) {
    diffuse = simd::select(lit, diffuse + intensity * s.kd * nDotL, diffuse);
    Vec3P reflected = s.normal * (Float(2.0f) * nDotL) - toLight;
    Float rDotV = dot(reflected, s.toEye);
    Mask shiny = lit & (rDotV > Float(0.0f)) & (s.ks > Float(0.0f));
    if (simd::any(shiny))
        specular = simd::select(
            shiny,
            specular + simd::min(intensity * s.ks, Float(kMaxLight)) * simd::powPositive(rDotV, s.shininess),
            specular);
}

/// The fraction of a light's samples that reached it, as the reference path
/// works it out: float(visible) / float(samples).
inline Float visibleFraction(Int visible, std::uint32_t samples) {
    return simd::toFloat(visible) / Float(float(samples));
}

/// The most nodes a soft sun's shadow rays start from, per packet (packetEntryNodes()).
constexpr std::size_t kPacketEntryNodes = 8;

/// Colours (0..1, unclamped) of a packet's surfaces lit by the frame's lights,
/// background where nothing was hit. The shadow rays toward light i start
/// from shadowEntry[i].nodes (Bvh::beamEntryNodes of a box holding their
/// origins; for a soft sun narrowed to this packet's beam first), or from
/// the root for lights past the end of shadowEntry.
inline ColorP shadeSurfaces(const PreparedFrame& frame, const PacketSurface& s,
                            std::span<const LightEntry> shadowEntry, RayCounts& counts) {
    ColorP out{Float(frame.background.x), Float(frame.background.y), Float(frame.background.z)};
    if (simd::none(s.hitLanes)) return out;
    const std::uint32_t root = 0;
    Float diffuse = s.unlit;
    Float specular(0.0f);
    for (std::size_t i = 0; i < frame.lights.size(); ++i) {
        const LightSample& light = frame.lights[i];
        Vec3P toLight(light.toLight);
        Float nDotL = dot(s.normal, toLight);
        Mask lit = s.hitLanes & (nDotL > Float(0.0f));
        if (simd::none(lit)) continue;
        Float intensity(light.intensity);
        std::span<const std::uint32_t> entry =
            i < shadowEntry.size() ? shadowEntry[i].nodes : std::span{&root, 1};
        if (light.sampleCount == 0) {
            counts.shadow += laneCount(lit);
            lit = simd::andNot(lit, occludedPacket(frame.bvh, ParallelRays(s.shadowOrigin, light.toLight),
                                                   lit, Float(0.0f), Float(kInfinity), s.skip, entry));
        } else {
            // One beam test per node for all the samples, instead of one per sample.
            std::uint32_t narrowed[kPacketEntryNodes];
            if (i < shadowEntry.size()) {
                const std::size_t n =
                    packetEntryNodes(frame.bvh, shadowEntry[i], s.shadowOrigin, lit, s.skip, narrowed);
                if (n <= kPacketEntryNodes) entry = {narrowed, n};
            }
            Int visible =
                visibleSunSamplesP(frame, light, s.shadowOrigin, s.normal, s.skip, lit, entry, counts);
            lit = lit & (Int(0) < visible);
            intensity = intensity * visibleFraction(visible, light.sampleCount);
        }
        if (simd::none(lit)) continue;
        addPhongP(s, toLight, nDotL, intensity, lit, diffuse, specular);
    }
    for (const LocalLightSample& light : frame.localLights) {
        const LocalLightViewP view = viewLocalLightP(light, s.shadowOrigin);
        Float nDotL = dot(s.normal, view.toLight);
        Mask lit = s.hitLanes & (nDotL > Float(0.0f));
        if (simd::none(lit)) continue;
        Float intensity = localLightIntensityP(light, view, lit);
        lit = lit & (intensity > Float(0.0f));
        if (simd::none(lit)) continue;
        if (light.sampleCount == 0) {
            lit = simd::andNot(lit, localLightBlockedP(frame, light, view, s.skip, lit, counts));
        } else {
            Int visible =
                visibleDiscSamplesP(frame, light, view, s.shadowOrigin, s.normal, s.skip, lit, counts);
            lit = lit & (Int(0) < visible);
            intensity = intensity * visibleFraction(visible, light.sampleCount);
        }
        if (simd::none(lit)) continue;
        addPhongP(s, view.toLight, nDotL, intensity, lit, diffuse, specular);
    }
    diffuse = simd::min(diffuse, Float(kMaxLight));  // see kMaxLight: no 0 * inf in a black channel
    out.r = simd::select(s.hitLanes, s.color.x * diffuse + specular, out.r);
    out.g = simd::select(s.hitLanes, s.color.y * diffuse + specular, out.g);
    out.b = simd::select(s.hitLanes, s.color.z * diffuse + specular, out.b);
    return out;
}

/// Lane version of toByte(): floor(255 * clamp(v) + 0.5), NaN -> 0.
inline Int toBytes(Float v) {
    v = simd::min(simd::max(v, Float(0.0f)), Float(1.0f));
    return simd::truncateToInt(simd::floor(Float(255.0f) * v + Float(0.5f)));
}

}  // namespace f2
