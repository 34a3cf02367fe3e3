#pragma once
/// Bounding volume hierarchy over one frame's primitives (binned SAH), rebuilt
/// every frame because everything may move. Buffers are reused across builds.
#include <cstdint>
#include <span>
#include <vector>

#include "core/geometry/intersect.h"

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
        std::uint32_t count = 0;  ///< primitives in a leaf, 0 for an inner node
    };

    void build(std::span<const Primitive> primitives);

    /// Closest hit within (tMin, tMax).
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit) const;
    /// Any hit within (tMin, tMax): shadow rays stop at the first occluder.
    bool occluded(const Ray& ray, float tMin, float tMax) const;

    std::span<const Node> nodes() const { return nodes_; }
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
