#pragma once
/// Bounding volume hierarchy over one frame's primitives (binned SAH). The
/// renderer keeps it from frame to frame: update() refits it to the moved
/// primitives and rebuilds it only when its quality has drifted too far.
/// Buffers are reused across builds.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "core/geometry/intersect.h"
#include "core/geometry/ray_mask.h"
#include "core/geometry/traversal_count.h"
#include "core/util/thread_pool.h"

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

    /// Full binned-SAH build over `primitives` (primitive bounds on the pool's threads if given).
    void build(std::span<const Primitive> primitives, ThreadPool* pool = nullptr);

    /// This frame's tree: refits the last tree to the moved primitives (same
    /// count, any motion: the result is always correct), and rebuilds it when
    /// there is none or refitting has let its SAH cost grow by kRebuildGrowth.
    /// A tree of kStagedBuildMin primitives or more is rebuilt in stages
    /// instead, from kStagedGrowth on: the new tree is split from the bounds of
    /// the frame that found the old one worn, a share of the splitting per
    /// call, while the old one goes on being refitted; once complete it
    /// replaces the old one (refitted to the frame at hand). The share is 1/k
    /// of a whole build, for k (2 to kMaxStagedFrames) two thirds of the frames
    /// the old tree can go on wearing at its last frame's pace before it
    /// reaches kRebuildNowGrowth; with less room the tree is rebuilt whole at
    /// kRebuildGrowth as a small one is, and if it gets to kRebuildNowGrowth
    /// anyway, at once. Meanwhile, and otherwise, the subtrees whose own SAH cost has
    /// grown by kSubtreeRebuildGrowth since they were built are rebuilt, the
    /// worst first, up to 1/kSubtreeBudget of the primitives per call. So
    /// playback pays for its rebuilds a little every frame instead of all at
    /// once now and then. Any tree gives the same hits (ties go to the lowest
    /// frame index), so images do not depend on which one was used.
    /// Returns true when the tree is a new one (built whole, or a staged one put in).
    bool update(std::span<const Primitive> primitives, ThreadPool* pool = nullptr);
    /// Writes every primitive of this frame into leaf order, primitive i into
    /// leaves[leafOf[i]] (and wherever else the caller keeps it): see below.
    using LeafWriter =
        std::function<void(std::span<const std::uint32_t> leafOf, std::span<Primitive> leaves)>;
    /// update() when the caller evaluates the frame's primitives itself,
    /// straight into the tree's leaf order: `write` is called once, before the
    /// refit, instead of the copy of `primitives` into leaf order. `primitives`
    /// (the frame, in its own order) must hold every primitive once `write` has
    /// returned: the writer fills it too, and rebuilds read it. Requires
    /// refits(primitives.size()).
    bool update(std::span<const Primitive> primitives, const LeafWriter& write, ThreadPool* pool);
    /// True when update() of `count` primitives starts by refitting the last tree.
    bool refits(std::size_t count) const { return !nodes_.empty() && count == ordered_.size(); }
    static constexpr float kRebuildGrowth = 1.3f;
    static constexpr float kStagedGrowth = 1.25f;
    static constexpr float kRebuildNowGrowth = 1.6f;
    static constexpr float kSubtreeRebuildGrowth = 1.1f;
    static constexpr std::uint32_t kSubtreeBudget = 16;
    static constexpr std::uint32_t kStagedBuildMin = 4096;
    static constexpr std::uint32_t kMaxStagedFrames = 8;
    /// Subtrees rebuilt by the last update() (0 after a full rebuild).
    std::uint32_t subtreesRebuilt() const { return lastUpdate_.subtreesRebuilt; }
    /// What one update() did to the tree.
    enum class UpdateAction : std::uint8_t {
        Refit,     ///< refitted only
        Subtrees,  ///< refitted, then degraded subtrees rebuilt
        Staged,    ///< refitted while a staged rebuild advanced
        Swapped,   ///< a staged rebuild completed: the new tree put in and refitted
        Rebuilt,   ///< built whole in this call (no tree yet, another primitive count, or a small tree worn)
    };
    /// What the last update() did, for logs and tests.
    struct UpdateReport {
        UpdateAction action = UpdateAction::Rebuilt;
        std::uint32_t subtreesRebuilt = 0;
        std::uint32_t primitivesRebuilt = 0;  ///< in rebuilt subtrees, or every one for a new tree
        /// Splitting done in this call: the primitives of every node split or
        /// made a leaf, summed (a full build of n primitives is about n * depth).
        std::uint64_t splitWork = 0;
        float costGrowth = 0;  ///< refitted SAH cost / cost at the last full build (0: not refitted)
    };
    const UpdateReport& lastUpdate() const { return lastUpdate_; }

    /// Expected cost of a ray under the SAH model, relative to the root's area.
    float sahCost() const;
    /// Nodes reachable from the root (nodes().size() also counts slots freed by subtree rebuilds).
    std::size_t liveNodeCount() const;

    static constexpr std::uint32_t kNoPrimitive = 0xFFFFFFFFu;
    /// Closest hit within (tMin, tMax) on a primitive other than `skip` (mirrored
    /// rays skip the convex primitive they leave); of hits at the same distance,
    /// the primitive first in the frame (lowest index), whatever the tree's shape.
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit,
                   std::uint32_t skip = kNoPrimitive) const;
    /// The same traversal, adding the boxes and primitives it tests to `count`.
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit, TraversalCount& count) const;
    bool intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit, NoTraversalCount&) const {
        return intersect(ray, tMin, tMax, hit);
    }
    /// Any hit within (tMin, tMax) on a primitive other than `skip`: shadow rays
    /// stop at the first occluder. A convex primitive cannot shadow its own lit
    /// side, so shadow rays skip the primitive they start on.
    bool occluded(const Ray& ray, float tMin, float tMax, std::uint32_t skip = kNoPrimitive) const;
    /// The same traversal, adding the boxes and primitives it tests to `count`.
    bool occluded(const Ray& ray, float tMin, float tMax, std::uint32_t skip, TraversalCount& count) const;
    bool occluded(const Ray& ray, float tMin, float tMax, std::uint32_t skip, NoTraversalCount&) const {
        return occluded(ray, tMin, tMax, skip);
    }

    /// Up to out.size() nodes whose subtrees hold every primitive that a ray
    /// inside `frustum` can reach, nearest to `eye` first; returns how many.
    /// From the root, the node with the largest box is replaced by those of its
    /// children the frustum does not exclude, while they fit: a tile's packets
    /// then skip the top of the tree, which every one of them would walk alike.
    std::size_t entryNodes(const Frustum& frustum, Vec3 eye, std::span<std::uint32_t> out) const;
    /// entryNodes() for the parallel rays that leave any point of `origins`
    /// along `direction`: the shadow rays of one tile toward one light.
    std::size_t beamEntryNodes(const Bounds& origins, Vec3 direction, std::span<std::uint32_t> out) const;
    /// The same for rays along any of `directions` (the samples of a soft
    /// sun): a node is left out only when no direction reaches it.
    std::size_t beamEntryNodes(const Bounds& origins, std::span<const Vec3> directions,
                               std::span<std::uint32_t> out) const;

    /// The ray_mask flags of the primitives, by frame index: shadow rays pass
    /// through those with any flag (`/no_shadow`, hidden), every ray through
    /// the hidden ones. Empty (the default): none. The mask is held by
    /// reference and must outlive the traversals.
    void setRayMask(std::span<const std::uint8_t> mask) { rayMask_ = mask; }
    std::span<const std::uint8_t> rayMask() const { return rayMask_; }

    /// The tree, for the packet traversal (bvh_packet.h) and tests.
    std::span<const Node> nodes() const { return nodes_; }
    /// Primitives in leaf order, and each one's index in the frame.
    std::span<const Primitive> orderedPrimitives() const { return ordered_; }
    std::span<const std::uint32_t> originalIndices() const { return original_; }

   private:
    /// The single-ray traversals, over a counting policy (traversal_count.h).
    template <class Count>
    bool intersectCounted(const Ray& ray, float tMin, float tMax, HitRecord& hit, std::uint32_t skip,
                          Count& count) const;
    template <class Count>
    bool occludedCounted(const Ray& ray, float tMin, float tMax, std::uint32_t skip, Count& count) const;

    /// The splitting of entryNodes(): nodes that `excludes` rejects are
    /// dropped, the rest are sorted by `distance`.
    template <class Excludes, class Distance>
    std::size_t entryNodesWhere(const Excludes& excludes, const Distance& distance,
                                std::span<std::uint32_t> out) const;

    std::vector<Node> nodes_;
    std::vector<Primitive> ordered_;         ///< primitives in leaf order
    std::vector<std::uint32_t> original_;    ///< ordered index -> frame index
    std::vector<std::uint32_t> position_;    ///< frame index -> ordered index
    std::span<const std::uint8_t> rayMask_;  ///< setRayMask()
    // Build scratch, kept to avoid per-frame allocation.
    std::vector<Bounds> primBounds_;
    std::vector<Vec3> centroids_;
    std::vector<std::uint32_t> indices_;
    float costAtBuild_ = 0;  ///< sahCost() right after the last full build

    /// Build: one task splits the primitives [begin, end) into the subtree at `node`.
    struct BuildTask {
        std::uint32_t node, begin, end, depth;
    };
    /// Makes out[task.node] a leaf over in.indices[task.begin, task.end), or
    /// splits it there: appends its child pair to `out`, puts their tasks in
    /// `children` (left, right) and returns true.
    struct SplitInput {
        const Bounds* bounds;    ///< by frame index
        const Vec3* centroids;   ///< by frame index
        std::uint32_t* indices;  ///< the leaf order being sorted
    };
    bool splitNode(const SplitInput& in, std::vector<Node>& out, const BuildTask& task,
                   BuildTask (&children)[2]);
    /// Splits `root` depth first, appending child pairs to `out`; tasks of fewer
    /// than `deferBelow` primitives (other than the root) go to deferred_ instead.
    /// Returns its split work (UpdateReport::splitWork).
    std::uint64_t buildNodes(std::span<const Primitive> primitives, std::vector<Node>& out, BuildTask root,
                             std::uint32_t deferBelow);
    /// The bounds and centroids of `primitives`, and indices in frame order.
    static void snapshotBounds(std::span<const Primitive> primitives, ThreadPool* pool,
                               std::vector<Bounds>& bounds, std::vector<Vec3>& centroids,
                               std::vector<std::uint32_t>& indices);
    std::vector<BuildTask> deferred_;              ///< subtrees set aside for the pool
    std::vector<std::vector<Node>> subtreeNodes_;  ///< their nodes, before they are appended

    /// Refit work, planned after each build: the subtrees below kRefitDepth
    /// are refitted in parallel, then the few nodes above them in turn.
    struct Subtree {
        std::uint32_t root, begin, end;  ///< its descendants: refitOrder_[begin, end), in pre-order
        std::uint32_t firstPrimitive, endPrimitive;  ///< its leaves' range of ordered_
    };
    std::vector<Subtree> subtrees_;
    std::vector<std::uint32_t> refitOrder_;
    std::vector<std::uint32_t> topNodes_;      ///< nodes above the subtrees, children before parents
    std::vector<float> subtreeCost_;           ///< each subtree's share of the SAH sum, per refit
    std::vector<float> subtreeCostAtBuild_;    ///< the same right after the subtree was (re)built
    std::vector<std::uint32_t> freePairs_;     ///< child-pair slots of nodes_ that rebuilds left unused
    std::vector<std::uint32_t> rebuildList_;   ///< subtrees chosen by the last update()
    std::vector<std::uint32_t> rebuildSlots_;  ///< placeSubtree() scratch
    std::vector<Subtree> subtreesBefore_;      ///< rebuildDegradedSubtrees() scratch
    std::vector<float> costAtBuildBefore_;     ///< rebuildDegradedSubtrees() scratch
    std::vector<std::uint64_t> subtreeWork_;   ///< rebuildDegradedSubtrees() scratch: split work per subtree
    UpdateReport lastUpdate_;

    /// A staged rebuild (see update()): the new tree's nodes and the splits
    /// still to do, over a snapshot of the bounds, with the leaf order taking
    /// shape in `indices`. Its own arrays, so that subtree rebuilds of the old
    /// tree go on meanwhile.
    struct StagedBuild {
        bool active = false;
        std::vector<Bounds> bounds;
        std::vector<Vec3> centroids;
        std::vector<std::uint32_t> indices;
        std::vector<Node> nodes;
        std::vector<BuildTask> tasks;
        std::uint64_t budget = 0;  ///< split work per call
        std::uint64_t work = 0;    ///< split work so far
    };
    std::uint64_t lastBuildWork_ = 0;  ///< split work of the tree in use (whole or staged build)
    float lastGrowth_ = 1;             ///< its refitted cost / cost at build, last update
    StagedBuild staged_;
    void startStagedBuild(std::span<const Primitive> primitives, ThreadPool* pool);
    /// Does the staged splits, depth first, up to `budget` work; true when none is left.
    bool advanceStagedBuild(std::uint64_t budget);
    /// Puts the completed staged tree in place of the old one (refit() then fills its leaves and boxes).
    void installStagedBuild();
    /// Records the refitted cost of a tree just built as its cost at build, whole and per subtree.
    void recordCostAtBuild(float cost);
    struct PlanItem {
        std::uint32_t node, depth;
    };
    std::vector<PlanItem> planStack_;
    void planRefit();
    /// Recomputes one node: a leaf from its (already copied) primitives, an inner node from its children.
    /// Returns its term of the SAH sum.
    float refitNode(std::uint32_t index);

    /// Recomputes every node's bounds from `primitives` (same count as built),
    /// copied into leaf order, or written there by `write` when given; returns sahCost().
    float refit(std::span<const Primitive> primitives, ThreadPool* pool, const LeafWriter* write);
    /// update(), with or without a writer.
    bool refitOrRebuild(std::span<const Primitive> primitives, ThreadPool* pool, const LeafWriter* write);
    /// SAH sum (unnormalised) of subtree k's nodes, its root included.
    float subtreeSahSum(std::size_t k) const;
    /// Rebuilds the degraded subtrees (see update()), on the pool's threads.
    void rebuildDegradedSubtrees(std::span<const Primitive> primitives, ThreadPool* pool);
    /// Moves subtree k's freshly built nodes (`local`, root first, then child
    /// pairs) into nodes_: its old child-pair slots first, then freed ones, then new.
    void placeSubtree(const Subtree& subtree, const std::vector<Node>& local);
};

}  // namespace f2
