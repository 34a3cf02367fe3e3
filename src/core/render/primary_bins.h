#pragma once
/// The primary rays of a large frame without the walk from the top of the
/// BVH: a cut through the tree, binned by where on the pinhole camera's image
/// its nodes can appear. Going down from the root, nearer child first, a node
/// whose box projects onto few cells of kCellWidth x kCellHeight pixels (a
/// packet's block) is listed in each of them, so that a packet walks only the
/// subtrees of its cell (findSurfaces, packet_shading.h), roughly nearest
/// first. The bins are exact: a cell lists every subtree holding a primitive
/// that a ray through it can hit, so a packet finds the hits the walk from the
/// root finds, bit for bit. Rebuilt for every frame and camera.
#include <cstdint>
#include <span>
#include <vector>

#include "core/geometry/bvh.h"
#include "core/render/camera.h"
#include "core/util/thread_pool.h"

namespace f2 {

/// A cut through a frame's BVH, binned by the image cells of its pinhole camera.
class PrimaryBins {
   public:
    /// A cell is a packet's block of pixels (4x4 with AVX-512; narrower blocks fit inside one).
    static constexpr int kCellWidth = 4, kCellHeight = 4;
    /// Pixels added around each projected box. The projection's own rounding
    /// is bounded separately (far below 0.01 pixel on screen); this is a safety margin.
    static constexpr float kMarginPixels = 0.25f;
    /// A node is listed (not split further) when its box covers at most this many cells.
    static constexpr std::uint64_t kCutCells = 4;
    /// Frames with fewer primitives use the tiles' entry nodes: forced on,
    /// binning made robots:1 3 % slower, left the default scene as it was and
    /// made robots:100 2 % and robots:1000 11 % faster (docs/performance.md §5, round 6).
    static constexpr std::size_t kMinPrimitives = 512;
    /// Leaves whose box reaches the eye plane (or covers a quarter of the
    /// image) are walked by every packet; with more of them the frame uses the
    /// tiles' entry nodes.
    static constexpr std::size_t kMaxEverywhere = 16;
    /// With more candidates than this per cell on average, the same.
    static constexpr std::size_t kMaxMeanCandidates = 24;

    /// Bins a cut through `bvh` for the primary rays of `camera`, or decides
    /// that this frame is better traced through the tiles' entry nodes
    /// (active() false): fewer than `minPrimitives` primitives, too many
    /// leaves everywhere, too many candidates, or a box that is not finite.
    /// Subtrees are cut on the pool's threads (if given). `marginPixels` is
    /// for tests (a margin too small must make them fail).
    void build(const Bvh& bvh, const Camera& camera, ThreadPool* pool,
               std::size_t minPrimitives = kMinPrimitives, float marginPixels = kMarginPixels);

    /// Whether the last build() binned the frame.
    bool active() const { return active_; }

    /// Leaves that every packet walks: those whose box reaches the eye plane.
    std::span<const std::uint32_t> everywhere() const { return everywhere_; }

    /// Nodes listed in the cell holding pixel (x, y): with everywhere(), their
    /// subtrees hold every primitive that a primary ray through the cell can hit.
    std::span<const std::uint32_t> cell(int x, int y) const {
        const std::size_t c = std::size_t(y / kCellHeight) * cellsX_ + std::size_t(x / kCellWidth);
        return {entries_.data() + cellStart_[c], entries_.data() + cellStart_[c + 1]};
    }

    /// Candidates listed in all cells, and nodes of the cut (for measurements and tests).
    std::size_t entryCount() const { return entries_.size(); }
    std::size_t cutSize() const { return cut_.size(); }

   private:
    /// Where a box can appear: cells [x0, x1] x [y0, y1].
    struct Footprint {
        std::uint16_t x0, y0, x1, y1;
    };
    /// A node of the cut.
    struct Listed {
        Footprint footprint;
        std::uint32_t node;
    };
    /// Where one box lies for the camera.
    struct Projection {
        enum Kind { Behind, OffImage, AtEyePlane, OnImage, NotFinite } kind = Behind;
        Footprint footprint{};
        std::uint64_t cells = 0;
    };
    /// The projections of nodes[indices[0..count)] (count <= the SIMD width)
    /// for the camera of the current build().
    void projectBatch(std::span<const Bvh::Node> nodes, const std::uint32_t* indices, std::size_t count,
                      Projection* out) const;
    /// One walk down the tree: its part of the cut and of everywhere(), and its stack.
    struct Walk {
        std::vector<Listed> cut;
        std::vector<std::uint32_t> everywhere, stack;
        bool finite = true;
    };
    /// Walks down from the nodes on walk.stack until it is empty or holds `stopAt` nodes.
    void descend(std::span<const Bvh::Node> nodes, Walk& walk, std::size_t stopAt) const;
    /// Fills cut_ and everywhere_ from the root, subtrees on the pool's threads;
    /// false on a box that is not finite.
    bool cutTree(std::span<const Bvh::Node> nodes, ThreadPool* pool);

    bool active_ = false;
    std::size_t cellsX_ = 0, cellsY_ = 0;
    std::vector<std::uint32_t> everywhere_;
    std::vector<std::uint32_t> entries_;
    std::vector<std::uint32_t> cellStart_;  ///< cellsX_ * cellsY_ + 1 offsets into entries_
    // The camera of the current build(), as projectBatch() reads it.
    struct View {
        Vec3 eye, right, up, forward, absRight, absUp, absForward;
        bool upperFirst[3];  ///< per axis, whether the upper child of a split is the nearer
        float width, height, scaleX, scaleY, margin;
        Frustum frustum;     ///< of the whole image
        std::uint64_t wide;  ///< a leaf covering more cells than this is walked by every packet
    } view_{};
    // Per-frame scratch, kept for its capacity.
    std::vector<Listed> cut_;
    Walk top_;
    std::vector<Walk> walks_;
};

}  // namespace f2
