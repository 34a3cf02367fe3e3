#pragma once
/// What a BVH traversal did, counted as it does it: the cost view's numbers.
/// The traversal is one template over a counting policy, so the counter is
/// the real work of the real traversal, and NoTraversalCount (the render
/// path) compiles to nothing.
#include <cstdint>

namespace f2 {

/// Counts the work of Bvh::intersect / Bvh::occluded calls.
struct TraversalCount {
    std::uint32_t nodes = 0;       ///< node boxes tested (a ray missing the root's box: 1)
    std::uint32_t primitives = 0;  ///< primitive intersection tests
    std::uint32_t total() const { return nodes + primitives; }
    void node() { ++nodes; }
    void primitive() { ++primitives; }
};

/// The counting policy of the normal path: counts nothing, costs nothing.
struct NoTraversalCount {
    void node() {}
    void primitive() {}
};

}  // namespace f2
