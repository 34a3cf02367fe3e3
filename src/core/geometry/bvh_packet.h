#pragma once
/// Packet traversal of a Bvh: simd::kWidth rays descend the tree together.
/// Private to the core: its types depend on the SIMD width the core is built
/// for (-march), so no public header may include it.
#include <span>

#include "core/geometry/bvh.h"
#include "core/geometry/packet.h"

namespace f2 {

/// Nearest hits of the `active` lanes within (tMin, hit.t): narrows hit.t (the
/// lanes' tMax on entry) and sets primitive, frameIndex and face. Of hits at the
/// same distance the lowest frame index wins, as in Bvh::intersect(const Ray&). Primitives are named by
/// their leaf-order index (Bvh::orderedPrimitives()), whose data the traversal
/// has just brought into cache; Bvh::originalIndices() maps back.
void intersectPacket(const Bvh& bvh, const EyeRays& rays, Mask active, Float tMin, PacketHit& hit);
/// The same, for rays that all lie inside one frustum: the traversal starts
/// from `roots`, the Bvh::entryNodes() of that frustum, instead of the root.
void intersectPacket(const Bvh& bvh, const EyeRays& rays, Mask active, Float tMin, PacketHit& hit,
                     std::span<const std::uint32_t> roots);

/// The same from the subtrees of `roots` and then of `moreRoots` (any number
/// of them: the nodes listed for one packet by PrimaryBins), nearest first.
void intersectPacket(const Bvh& bvh, const EyeRays& rays, Mask active, Float tMin, PacketHit& hit,
                     std::span<const std::uint32_t> roots, std::span<const std::uint32_t> moreRoots);

/// Nearest hits, as above, of rays that share nothing (mirrored rays), from the
/// root, on primitives other than each lane's `skip` (leaf order).
void intersectPacket(const Bvh& bvh, const FreeRays& rays, Mask active, Float tMin, PacketHit& hit, Int skip);

/// Lanes of `active` that hit something within (tMin, tMax) other than their
/// `skip` primitive (leaf order).
Mask occludedPacket(const Bvh& bvh, const ParallelRays& rays, Mask active, Float tMin, Float tMax, Int skip);
/// The same, for rays that all start inside one box: the traversal starts
/// from `roots`, the Bvh::beamEntryNodes() of that box and direction.
Mask occludedPacket(const Bvh& bvh, const ParallelRays& rays, Mask active, Float tMin, Float tMax, Int skip,
                    std::span<const std::uint32_t> roots);
/// The same for rays that leave one point (a point light toward the surfaces
/// it lights) and for rays that share nothing (from the samples of a soft
/// light's disc), from the root.
Mask occludedPacket(const Bvh& bvh, const EyeRays& rays, Mask active, Float tMin, Float tMax, Int skip);
Mask occludedPacket(const Bvh& bvh, const FreeRays& rays, Mask active, Float tMin, Float tMax, Int skip);

}  // namespace f2
