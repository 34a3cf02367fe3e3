#pragma once
/// Bounding volume hierarchy over one frame's primitives (binned SAH), rebuilt
/// every frame because everything may move. Buffers are reused across builds.
#include <cstdint>
#include <span>
#include <vector>

#include "core/geometry/intersect.h"
#include "core/geometry/packet.h"

namespace f2 {

/// Nearest hit found by Bvh::intersect.
struct HitRecord {
    float t = kInfinity;
    std::uint32_t primitive = 0;  ///< index into the frame's primitives
    Face face = Face::Curved;
};

class Bvh {
public:
    /// Node of the flattened tree; children of an inner node are adjacent.
    struct Node {
        Bounds bounds;
        std::uint32_t first = 0;  ///< leaf: first ordered primitive; inner: left child
        std::uint16_t count = 0;  ///< primitives in a leaf (at most 16), 0 for an inner node
        std::uint16_t axis = 0;   ///< inner: split axis; the left child holds the lower side
    };

    void build(std::span<const Primitive> primitives);

    /// Closest hit within (tMin, tMax).
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const;
    /// Any hit within (tMin, tMax): shadow rays stop at the first occluder.
    bool occluded(const Ray& ray, float tMin, float tMax) const;

    /// Packet versions: the `active` lanes traverse together; results as above per lane.
    /// intersect() narrows hit.t (the lanes' tMax on entry) and sets primitive and face.
    void intersect(const RayPacket& rays, Mask active, Float tMin, PacketHit& hit) const;
    /// Lanes of `active` that hit something within (tMin, tMax).
    Mask occluded(const RayPacket& rays, Mask active, Float tMin, Float tMax) const;

    std::span<const Node> nodes() const { return nodes_; }
    /// Primitives in leaf order, and each one's index in the frame.
    std::span<const Primitive> orderedPrimitives() const { return ordered_; }
    std::span<const std::uint32_t> originalIndices() const { return original_; }
    Bounds bounds() const { return nodes_.empty() ? Bounds{} : nodes_[0].bounds; }

private:
    std::vector<Node> nodes_;
    std::vector<Primitive> ordered_;        ///< primitives in leaf order
    std::vector<std::uint32_t> original_;   ///< ordered index -> frame index
    // Build scratch, kept to avoid per-frame allocation.
    std::vector<Bounds> primBounds_;
    std::vector<Vec3> centroids_;
    std::vector<std::uint32_t> indices_;
};

}  // namespace f2
