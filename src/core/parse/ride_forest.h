#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace f2::parsing {

/// The rides at one time as a rooted forest, each object under the object it
/// rides on, which links, cuts and finds the top of a tree in amortized
/// O(log n) (a link-cut tree: Sleator and Tarjan; splay trees over the
/// preferred paths, no reversal since only tops are linked). Lets
/// `/attach … at` check cycles per interval in O(k log n) for k changes.
class RideForest {
   public:
    explicit RideForest(std::size_t n) : nodes_(n + 1) {}

    /// `child`, the top of its tree, now rides on `parent` (not in its tree).
    void link(std::uint32_t child, std::uint32_t parent) {
        const std::uint32_t c = child + 1;
        access(c);
        nodes_[c].parent = parent + 1;
    }
    /// `child` rides on nothing now (it may ride on nothing already).
    void cut(std::uint32_t child) {
        const std::uint32_t c = child + 1;
        access(c);
        if (const std::uint32_t above = nodes_[c].kid[0]) {
            nodes_[above].parent = 0;
            nodes_[c].kid[0] = 0;
        }
    }
    /// The top of the tree `x` is in: the object its chain of rides ends at.
    std::uint32_t top(std::uint32_t x) {
        std::uint32_t v = x + 1;
        access(v);
        while (nodes_[v].kid[0]) v = nodes_[v].kid[0];
        splay(v);
        return v - 1;
    }

   private:
    struct Node {
        std::uint32_t parent = 0;            ///< in its splay tree, or the path's parent at a splay root
        std::array<std::uint32_t, 2> kid{};  ///< 0: nearer the top, 1: farther
    };
    bool isSplayRoot(std::uint32_t x) const {
        const Node& p = nodes_[nodes_[x].parent];
        return nodes_[x].parent == 0 || (p.kid[0] != x && p.kid[1] != x);
    }
    void rotate(std::uint32_t x) {
        const std::uint32_t p = nodes_[x].parent, g = nodes_[p].parent;
        const int side = nodes_[p].kid[1] == x;
        if (!isSplayRoot(p)) nodes_[g].kid[nodes_[g].kid[1] == p] = x;
        nodes_[x].parent = g;
        const std::uint32_t moved = nodes_[x].kid[1 - side];
        nodes_[p].kid[side] = moved;
        if (moved) nodes_[moved].parent = p;
        nodes_[x].kid[1 - side] = p;
        nodes_[p].parent = x;
    }
    void splay(std::uint32_t x) {
        while (!isSplayRoot(x)) {
            const std::uint32_t p = nodes_[x].parent;
            if (!isSplayRoot(p)) {
                const std::uint32_t g = nodes_[p].parent;
                rotate((nodes_[g].kid[1] == p) == (nodes_[p].kid[1] == x) ? p : x);
            }
            rotate(x);
        }
    }
    /// Makes the path from x's top to x preferred, x at its splay root with nothing below it.
    void access(std::uint32_t x) {
        for (std::uint32_t below = 0, v = x; v; below = v, v = nodes_[v].parent) {
            splay(v);
            nodes_[v].kid[1] = below;
        }
        splay(x);
    }

    std::vector<Node> nodes_;  ///< object i is node i + 1; node 0 is none
};

}  // namespace f2::parsing
