#include "core/geometry/bvh.h"

#include <algorithm>
#include <atomic>
#include <cassert>

namespace f2 {

namespace {
constexpr int kBinCount = 16;
constexpr std::uint32_t kMaxLeafSize = 4;    // below this, no split is searched
constexpr std::uint32_t kMaxLeafCount = 16;  // Node::count is 16 bits; packets test leaves whole
constexpr float kTraversalCost = 1.0f;       // relative to one primitive test
// Past this depth SAH gives way to median splits, which halve the count, so a
// hostile layout cannot make the tree deeper than the traversal stack.
constexpr std::uint32_t kMaxSahDepth = 64;
constexpr int kStackSize = 128;
constexpr std::uint32_t kRefitChunk = 1024;  // primitives per parallel work item of a build
// Depth of the subtrees refitted in parallel: up to 2^6 = 64 work items,
// enough to share unequal subtrees between threads.
constexpr std::uint32_t kRefitDepth = 6;
// Parallel build, for trees of kParallelBuildMin primitives or more: subtrees
// of fewer than n / (kPiecesPerThread * threads) primitives go to the pool.
// Fewer, bigger pieces measured best: the part above them is serial.
constexpr std::uint32_t kPiecesPerThread = 2;
constexpr std::uint32_t kParallelBuildMin = 4096;

/// body(chunk) for chunk in [0, chunks), on the pool when there is one.
template <class Body>
void forChunks(ThreadPool* pool, std::uint32_t chunks, Body&& body) {
    if (pool) {
        pool->parallelFor(chunks, body);
    } else {
        for (std::uint32_t c = 0; c < chunks; ++c) body(c);
    }
}

/// Bin of a centroid coordinate. Written so that coordinates near the float
/// limit (infinite or NaN offsets) still land in a valid bin.
inline int binOf(float coordinate, float lo, float scale) {
    float f = (coordinate - lo) * scale;
    if (!(f >= 0)) return 0;
    return f < float(kBinCount) ? int(f) : kBinCount - 1;
}

/// Slab test of a ray against a box; returns the entry distance or +inf.
inline float boxEntry(const Bounds& b, Vec3 origin, Vec3 invDir, float tMin, float tMax) {
    float tx0 = (b.lo.x - origin.x) * invDir.x, tx1 = (b.hi.x - origin.x) * invDir.x;
    float ty0 = (b.lo.y - origin.y) * invDir.y, ty1 = (b.hi.y - origin.y) * invDir.y;
    float tz0 = (b.lo.z - origin.z) * invDir.z, tz1 = (b.hi.z - origin.z) * invDir.z;
    // std::min/max with the NaN of 0*inf on the first argument ignore it.
    float enter =
        std::max(std::max(std::min(tx0, tx1), std::min(ty0, ty1)), std::max(std::min(tz0, tz1), tMin));
    float exit =
        std::min(std::min(std::max(tx0, tx1), std::max(ty0, ty1)), std::min(std::max(tz0, tz1), tMax));
    return enter <= exit ? enter : kInfinity;
}

inline Vec3 inverseDirection(Vec3 d) { return {1.0f / d.x, 1.0f / d.y, 1.0f / d.z}; }
}  // namespace

bool Bvh::splitNode(const SplitInput& in, std::vector<Node>& out, const BuildTask& task,
                    BuildTask (&children)[2]) {
    Bounds bounds, centroidBounds;
    for (std::uint32_t i = task.begin; i < task.end; ++i) {
        bounds.grow(in.bounds[in.indices[i]]);
        centroidBounds.grow(in.centroids[in.indices[i]]);
    }
    Node& node = out[task.node];
    node.bounds = bounds;
    std::uint32_t count = task.end - task.begin;

    // Find the best binned SAH split over the three axes.
    int bestAxis = -1, bestBin = 0;
    float bestCost = kInfinity;
    Vec3 extent = centroidBounds.hi - centroidBounds.lo;
    if (count > kMaxLeafSize && task.depth < kMaxSahDepth) {
        for (int axis = 0; axis < 3; ++axis) {
            if (!(extent[axis] > 0)) continue;
            Bounds binBounds[kBinCount];
            std::uint32_t binCount[kBinCount] = {};
            float scale = kBinCount / extent[axis];
            for (std::uint32_t i = task.begin; i < task.end; ++i) {
                std::uint32_t p = in.indices[i];
                int b = binOf(in.centroids[p][axis], centroidBounds.lo[axis], scale);
                binBounds[b].grow(in.bounds[p]);
                ++binCount[b];
            }
            // Sweep from the right, then from the left.
            float rightArea[kBinCount];
            std::uint32_t rightCount[kBinCount];
            Bounds acc;
            std::uint32_t accCount = 0;
            for (int b = kBinCount - 1; b > 0; --b) {
                acc.grow(binBounds[b]);
                accCount += binCount[b];
                rightArea[b] = accCount ? acc.halfArea() : 0;
                rightCount[b] = accCount;
            }
            acc = Bounds{};
            accCount = 0;
            for (int b = 0; b < kBinCount - 1; ++b) {
                acc.grow(binBounds[b]);
                accCount += binCount[b];
                if (accCount == 0 || rightCount[b + 1] == 0) continue;
                float cost = acc.halfArea() * accCount + rightArea[b + 1] * rightCount[b + 1];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = b;
                }
            }
        }
    }
    float leafCost = bounds.halfArea() * count;
    // A leaf when no split was searched or SAH prefers it; never more than kMaxLeafCount.
    bool makeLeaf =
        count <= kMaxLeafCount && (bestAxis < 0 || kTraversalCost * bounds.halfArea() + bestCost >= leafCost);
    if (makeLeaf) {
        node.first = task.begin;
        node.count = std::uint16_t(count);
        return false;
    }

    std::uint32_t* first = in.indices + task.begin;
    std::uint32_t* last = in.indices + task.end;
    std::uint32_t* middle;
    int splitAxis = bestAxis;
    if (bestAxis >= 0) {
        float scale = kBinCount / extent[bestAxis];
        float lo = centroidBounds.lo[bestAxis];
        middle = std::partition(first, last, [&](std::uint32_t p) {
            return binOf(in.centroids[p][bestAxis], lo, scale) <= bestBin;
        });
    } else {
        // No SAH split (too deep, or all centroids equal): object median on the widest axis.
        splitAxis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        middle = first + count / 2;
        std::nth_element(first, middle, last, [&](std::uint32_t a, std::uint32_t b) {
            return in.centroids[a][splitAxis] < in.centroids[b][splitAxis];
        });
    }
    std::uint32_t mid = std::uint32_t(middle - in.indices);
    std::uint32_t left = std::uint32_t(out.size());
    node.first = left;
    node.count = 0;
    node.axis = std::uint16_t(splitAxis);
    out.push_back({});  // `node` is not used past here: the push may move it
    out.push_back({});
    children[0] = {left, task.begin, mid, task.depth + 1};
    children[1] = {left + 1, mid, task.end, task.depth + 1};
    return true;
}

std::uint64_t Bvh::buildNodes(std::span<const Primitive> primitives, std::vector<Node>& out, BuildTask root,
                              std::uint32_t deferBelow) {
    BuildTask stack[kStackSize];
    int top = 0;
    stack[top++] = root;
    std::uint64_t work = 0;
    while (top > 0) {
        BuildTask task = stack[--top];
        if (task.end - task.begin < deferBelow && task.node != root.node) {
            deferred_.push_back(task);
            continue;
        }
        work += task.end - task.begin;
        BuildTask children[2];
        if (splitNode({primBounds_.data(), centroids_.data(), indices_.data()}, out, task, children)) {
            stack[top++] = children[1];
            stack[top++] = children[0];
            continue;
        }
        for (std::uint32_t i = task.begin; i < task.end; ++i) {
            ordered_[i] = primitives[indices_[i]];
            original_[i] = indices_[i];
            position_[indices_[i]] = i;
        }
    }
    return work;
}

void Bvh::snapshotBounds(std::span<const Primitive> primitives, ThreadPool* pool, std::vector<Bounds>& bounds,
                         std::vector<Vec3>& centroids, std::vector<std::uint32_t>& indices) {
    const std::uint32_t n = std::uint32_t(primitives.size());
    bounds.resize(n);
    centroids.resize(n);
    indices.resize(n);
    forChunks(pool, (n + kRefitChunk - 1) / kRefitChunk, [&](std::uint32_t chunk) {
        for (std::uint32_t i = chunk * kRefitChunk; i < std::min(n, (chunk + 1) * kRefitChunk); ++i) {
            bounds[i] = primitiveBounds(primitives[i]);
            centroids[i] = bounds[i].centroid();
            indices[i] = i;
        }
    });
}

void Bvh::build(std::span<const Primitive> primitives, ThreadPool* pool) {
    const std::uint32_t n = std::uint32_t(primitives.size());
    nodes_.clear();
    subtrees_.clear();
    topNodes_.clear();
    staged_.active = false;  // a staged rebuild of the old primitives has no use now
    staged_.tasks.clear();
    snapshotBounds(primitives, pool, primBounds_, centroids_, indices_);
    ordered_.resize(n);
    original_.resize(n);
    position_.resize(n);
    if (n == 0) return;

    nodes_.reserve(2 * n);
    nodes_.push_back({});
    // The top of the tree here; with a pool, smaller subtrees are set aside
    // and built on the pool's threads, each into its own array, then appended.
    const bool parallel = pool && pool->threadCount() > 1 && n >= kParallelBuildMin;
    deferred_.clear();
    std::uint64_t work =
        buildNodes(primitives, nodes_, {0, 0, n, 0},
                   parallel ? n / (kPiecesPerThread * std::uint32_t(pool->threadCount())) : 0);
    if (!deferred_.empty()) {
        if (subtreeNodes_.size() < deferred_.size()) subtreeNodes_.resize(deferred_.size());
        std::atomic<std::uint64_t> deferredWork{0};
        pool->parallelFor(std::uint32_t(deferred_.size()), [&](std::uint32_t k) {
            std::vector<Node>& local = subtreeNodes_[k];
            local.assign(1, Node{});
            BuildTask task = deferred_[k];
            deferredWork.fetch_add(buildNodes(primitives, local, {0, task.begin, task.end, task.depth}, 0),
                                   std::memory_order_relaxed);
        });
        work += deferredWork.load();
        for (std::size_t k = 0; k < deferred_.size(); ++k) {
            // Local node i > 0 lands at base + i - 1; local node 0 is the set-aside slot.
            const std::vector<Node>& local = subtreeNodes_[k];
            const std::uint32_t shift = std::uint32_t(nodes_.size()) - 1;
            for (std::size_t i = 0; i < local.size(); ++i) {
                Node node = local[i];
                if (node.count == 0) node.first += shift;
                if (i == 0)
                    nodes_[deferred_[k].node] = node;
                else
                    nodes_.push_back(node);
            }
        }
    }
    freePairs_.clear();
    planRefit();
    recordCostAtBuild(sahCost());
    lastUpdate_.splitWork = work;
    lastBuildWork_ = work;
    lastGrowth_ = 1;
}

void Bvh::recordCostAtBuild(float cost) {
    costAtBuild_ = cost;
    subtreeCostAtBuild_.resize(subtrees_.size());
    for (std::size_t k = 0; k < subtrees_.size(); ++k) subtreeCostAtBuild_[k] = subtreeSahSum(k);
}

void Bvh::startStagedBuild(std::span<const Primitive> primitives, ThreadPool* pool) {
    const std::uint32_t n = std::uint32_t(primitives.size());
    snapshotBounds(primitives, pool, staged_.bounds, staged_.centroids, staged_.indices);
    staged_.nodes.assign(1, Node{});
    staged_.tasks.assign(1, {0, 0, n, 0});
    staged_.work = 0;
    staged_.active = true;
}

bool Bvh::advanceStagedBuild(std::uint64_t budget) {
    std::uint64_t work = 0;
    while (!staged_.tasks.empty()) {
        const BuildTask task = staged_.tasks.back();
        const std::uint32_t size = task.end - task.begin;
        if (work > 0 && work + size > budget) break;
        staged_.tasks.pop_back();
        work += size;
        staged_.work += size;
        BuildTask children[2];
        if (splitNode({staged_.bounds.data(), staged_.centroids.data(), staged_.indices.data()},
                      staged_.nodes, task, children)) {
            staged_.tasks.push_back(children[1]);
            staged_.tasks.push_back(children[0]);
        }
    }
    lastUpdate_.splitWork += work;
    return staged_.tasks.empty();
}

void Bvh::installStagedBuild() {
    // Its leaves hold staged_.indices[first, first + count): that is the new leaf order.
    nodes_.swap(staged_.nodes);
    original_.assign(staged_.indices.begin(), staged_.indices.end());
    for (std::uint32_t i = 0; i < original_.size(); ++i) position_[original_[i]] = i;
    freePairs_.clear();
    planRefit();
    staged_.active = false;
    lastBuildWork_ = staged_.work;
}

namespace {
/// body(node) for every node reachable from the root: subtree rebuilds leave
/// unused slots in the array, which must not count.
template <class Body>
void forEachLiveNode(std::span<const Bvh::Node> nodes, Body&& body) {
    if (nodes.empty()) return;
    std::uint32_t stack[kStackSize];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Bvh::Node& node = nodes[stack[--top]];
        body(node);
        if (node.count == 0) {
            stack[top++] = node.first + 1;
            stack[top++] = node.first;
        }
    }
}
}  // namespace

float Bvh::sahCost() const {
    if (nodes_.empty()) return 0;
    float sum = 0;
    forEachLiveNode(nodes_, [&](const Node& node) {
        sum += node.bounds.halfArea() * (node.count > 0 ? float(node.count) : kTraversalCost);
    });
    float root = nodes_[0].bounds.halfArea();
    return root > 0 ? sum / root : 0;
}

std::size_t Bvh::liveNodeCount() const {
    std::size_t count = 0;
    forEachLiveNode(nodes_, [&](const Node&) { ++count; });
    return count;
}

void Bvh::planRefit() {
    subtrees_.clear();
    topNodes_.clear();
    refitOrder_.clear();
    std::vector<PlanItem>& stack = planStack_;
    stack.assign(1, {0, 0});
    while (!stack.empty()) {
        PlanItem item = stack.back();
        stack.pop_back();
        const Node& node = nodes_[item.node];
        if (node.count == 0 && item.depth == kRefitDepth) {
            // Its descendants in pre-order: walked backwards, children come before parents.
            std::uint32_t begin = std::uint32_t(refitOrder_.size());
            std::uint32_t firstPrimitive = ~0u, endPrimitive = 0;
            std::size_t below = stack.size();
            stack.push_back({node.first, 0});
            stack.push_back({node.first + 1, 0});
            while (stack.size() > below) {
                std::uint32_t index = stack.back().node;
                stack.pop_back();
                refitOrder_.push_back(index);
                const Node& child = nodes_[index];
                if (child.count == 0) {
                    stack.push_back({child.first, 0});
                    stack.push_back({child.first + 1, 0});
                } else {
                    firstPrimitive = std::min(firstPrimitive, child.first);
                    endPrimitive = std::max(endPrimitive, child.first + child.count);
                }
            }
            subtrees_.push_back(
                {item.node, begin, std::uint32_t(refitOrder_.size()), firstPrimitive, endPrimitive});
            continue;
        }
        topNodes_.push_back(item.node);  // leaves above the depth included
        if (node.count == 0) {
            stack.push_back({node.first, item.depth + 1});
            stack.push_back({node.first + 1, item.depth + 1});
        }
    }
    std::sort(topNodes_.begin(), topNodes_.end(), std::greater<>());  // children have larger indices
    subtreeCost_.assign(subtrees_.size(), 0.0f);
}

float Bvh::refitNode(std::uint32_t index) {
    Node& node = nodes_[index];
    if (node.count > 0) {
        Bounds b;
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
            b.grow(primitiveBounds(ordered_[i]));
        node.bounds = b;
        return b.halfArea() * float(node.count);
    }
    node.bounds = nodes_[node.first].bounds;
    node.bounds.grow(nodes_[node.first + 1].bounds);
    return node.bounds.halfArea() * kTraversalCost;
}

float Bvh::refit(std::span<const Primitive> primitives, ThreadPool* pool, const LeafWriter* write) {
    if (write) {
        (*write)(position_, ordered_);
    } else {
        // Copy the moved primitives into leaf order: reading the frame in order and
        // scattering the writes keeps the loads sequential (they would miss cache
        // gathered in leaf order).
        const std::uint32_t n = std::uint32_t(primitives.size());
        forChunks(pool, (n + kRefitChunk - 1) / kRefitChunk, [&](std::uint32_t chunk) {
            for (std::uint32_t i = chunk * kRefitChunk; i < std::min(n, (chunk + 1) * kRefitChunk); ++i)
                ordered_[position_[i]] = primitives[i];
        });
    }
    forChunks(pool, std::uint32_t(subtrees_.size()), [&](std::uint32_t k) {
        const Subtree& subtree = subtrees_[k];
        float sum = 0;
        for (std::uint32_t i = subtree.end; i-- > subtree.begin;) sum += refitNode(refitOrder_[i]);
        subtreeCost_[k] = sum + refitNode(subtree.root);
    });
    float sum = 0;
    for (float cost : subtreeCost_) sum += cost;
    for (std::uint32_t index : topNodes_) sum += refitNode(index);
    float root = nodes_[0].bounds.halfArea();
    return root > 0 ? sum / root : 0;
}

bool Bvh::update(std::span<const Primitive> primitives, ThreadPool* pool) {
    return refitOrRebuild(primitives, pool, nullptr);
}

bool Bvh::update(std::span<const Primitive> primitives, const LeafWriter& write, ThreadPool* pool) {
    assert(refits(primitives.size()));  // else nothing would write the frame
    return refitOrRebuild(primitives, pool, &write);
}

bool Bvh::refitOrRebuild(std::span<const Primitive> primitives, ThreadPool* pool, const LeafWriter* write) {
    lastUpdate_ = {};
    const std::uint32_t n = std::uint32_t(primitives.size());
    auto buildWhole = [&] {
        build(primitives, pool);
        lastUpdate_.action = UpdateAction::Rebuilt;
        lastUpdate_.primitivesRebuilt = n;
        return true;
    };
    if (!refits(n)) return buildWhole();
    const float cost = refit(primitives, pool, write);
    const float growth = costAtBuild_ > 0 ? cost / costAtBuild_ : 0;
    lastUpdate_.costGrowth = growth;
    lastUpdate_.action = UpdateAction::Refit;
    const float wear = growth - lastGrowth_;  // since the last frame
    lastGrowth_ = growth;
    if (!staged_.active) {
        const bool small = n < kStagedBuildMin;  // a whole build costs little
        std::uint32_t frames = 0;
        if (!small && growth > kStagedGrowth) {
            // Spread the rebuild over two thirds of the frames (up to
            // kMaxStagedFrames) the tree can go on wearing at its last frame's
            // pace before it reaches kRebuildNowGrowth (wear speeds up as boxes grow).
            const float room =
                wear > 0 ? (kRebuildNowGrowth - growth) / (1.5f * wear) : float(kMaxStagedFrames);
            frames = std::uint32_t(std::clamp(room, 0.0f, float(kMaxStagedFrames)));
        }
        if (frames < 2) {  // no staging: as for a small tree
            if (cost > costAtBuild_ * kRebuildGrowth) return buildWhole();
            rebuildDegradedSubtrees(primitives, pool);
            if (lastUpdate_.subtreesRebuilt > 0) lastUpdate_.action = UpdateAction::Subtrees;
            return false;
        }
        startStagedBuild(primitives, pool);
        staged_.budget = std::max<std::uint64_t>(n, (lastBuildWork_ + frames - 1) / frames);
    } else if (cost > costAtBuild_ * kRebuildNowGrowth) {
        // Things moved faster than the tree's pace so far: tracing with the
        // worn one would cost more than building a new one now.
        return buildWhole();
    } else {
        rebuildDegradedSubtrees(primitives, pool);  // the old tree is still the one traced
    }
    lastUpdate_.action = UpdateAction::Staged;
    if (!advanceStagedBuild(staged_.budget)) return false;
    // The new tree takes over. Its cost at build is that over the bounds it was
    // split from; refitted to this frame, it shows how far things moved since.
    installStagedBuild();
    recordCostAtBuild(sahCost());
    const float swappedCost = refit(primitives, pool, nullptr);  // the frame is whole by now
    lastUpdate_.action = UpdateAction::Swapped;
    lastUpdate_.primitivesRebuilt = n;
    lastUpdate_.costGrowth = costAtBuild_ > 0 ? swappedCost / costAtBuild_ : 0;
    lastGrowth_ = lastUpdate_.costGrowth;
    return true;
}

float Bvh::subtreeSahSum(std::size_t k) const {
    const Subtree& subtree = subtrees_[k];
    auto term = [&](std::uint32_t index) {
        const Node& node = nodes_[index];
        return node.bounds.halfArea() * (node.count > 0 ? float(node.count) : kTraversalCost);
    };
    float sum = term(subtree.root);
    for (std::uint32_t i = subtree.begin; i < subtree.end; ++i) sum += term(refitOrder_[i]);
    return sum;
}

void Bvh::rebuildDegradedSubtrees(std::span<const Primitive> primitives, ThreadPool* pool) {
    // The worst first: by how much each has grown past its cost at build.
    rebuildList_.clear();
    for (std::uint32_t k = 0; k < subtrees_.size(); ++k)
        if (subtreeCost_[k] > subtreeCostAtBuild_[k] * kSubtreeRebuildGrowth) rebuildList_.push_back(k);
    if (rebuildList_.empty()) return;
    std::sort(rebuildList_.begin(), rebuildList_.end(), [&](std::uint32_t a, std::uint32_t b) {
        float ga = subtreeCost_[a] - subtreeCostAtBuild_[a], gb = subtreeCost_[b] - subtreeCostAtBuild_[b];
        return ga != gb ? ga > gb : a < b;
    });
    const std::uint32_t budget = std::max<std::uint32_t>(1, std::uint32_t(ordered_.size()) / kSubtreeBudget);
    std::uint32_t spent = 0;
    std::size_t chosen = 0;
    for (; chosen < rebuildList_.size(); ++chosen) {
        const Subtree& subtree = subtrees_[rebuildList_[chosen]];
        std::uint32_t size = subtree.endPrimitive - subtree.firstPrimitive;
        if (chosen > 0 && spent + size > budget) break;
        spent += size;
    }
    rebuildList_.resize(chosen);
    lastUpdate_.subtreesRebuilt = std::uint32_t(chosen);
    lastUpdate_.primitivesRebuilt = spent;

    // Each subtree owns a contiguous range of ordered_: its primitives are
    // re-split there from their current bounds, into a local node array.
    if (subtreeNodes_.size() < chosen) subtreeNodes_.resize(chosen);
    std::vector<std::uint64_t>& subtreeWork = subtreeWork_;
    subtreeWork.assign(chosen, 0);
    forChunks(pool, std::uint32_t(chosen), [&](std::uint32_t j) {
        const Subtree& subtree = subtrees_[rebuildList_[j]];
        for (std::uint32_t i = subtree.firstPrimitive; i < subtree.endPrimitive; ++i) {
            const std::uint32_t p = original_[i];
            primBounds_[p] = primitiveBounds(primitives[p]);
            centroids_[p] = primBounds_[p].centroid();
            indices_[i] = p;
        }
        std::vector<Node>& local = subtreeNodes_[j];
        local.assign(1, Node{});
        subtreeWork[j] =
            buildNodes(primitives, local, {0, subtree.firstPrimitive, subtree.endPrimitive, kRefitDepth}, 0);
    });
    for (std::size_t j = 0; j < chosen; ++j) lastUpdate_.splitWork += subtreeWork[j];
    for (std::size_t j = 0; j < chosen; ++j) placeSubtree(subtrees_[rebuildList_[j]], subtreeNodes_[j]);

    // The refit plan follows the new shapes; the other subtrees keep their
    // build-time costs (found by root: the nodes above them have not changed).
    std::vector<Subtree>& before = subtreesBefore_;
    std::vector<float>& costBefore = costAtBuildBefore_;
    before.assign(subtrees_.begin(), subtrees_.end());
    costBefore.assign(subtreeCostAtBuild_.begin(), subtreeCostAtBuild_.end());
    planRefit();
    subtreeCostAtBuild_.assign(subtrees_.size(), 0.0f);
    std::size_t old = 0;
    for (std::size_t k = 0; k < subtrees_.size(); ++k) {
        while (old < before.size() && before[old].root != subtrees_[k].root) ++old;
        bool rebuilt = old == before.size() || std::find(rebuildList_.begin(), rebuildList_.end(),
                                                         std::uint32_t(old)) != rebuildList_.end();
        subtreeCostAtBuild_[k] = rebuilt ? subtreeSahSum(k) : costBefore[old];
    }
}

void Bvh::placeSubtree(const Subtree& subtree, const std::vector<Node>& local) {
    // The old child-pair slots: the `first` of every inner node of the subtree.
    std::vector<std::uint32_t>& slots = rebuildSlots_;
    slots.clear();
    auto collect = [&](std::uint32_t index) {
        if (nodes_[index].count == 0) slots.push_back(nodes_[index].first);
    };
    collect(subtree.root);
    for (std::uint32_t i = subtree.begin; i < subtree.end; ++i) collect(refitOrder_[i]);
    std::sort(slots.begin(), slots.end());
    // Local node 0 is the root; local pair j is nodes 2j + 1 and 2j + 2.
    const std::size_t pairs = (local.size() - 1) / 2;
    std::size_t reused = std::min(pairs, slots.size());
    for (std::size_t j = reused; j < slots.size(); ++j) freePairs_.push_back(slots[j]);
    slots.resize(reused);
    while (slots.size() < pairs) {
        if (!freePairs_.empty()) {
            slots.push_back(freePairs_.back());
            freePairs_.pop_back();
        } else {
            slots.push_back(std::uint32_t(nodes_.size()));
            nodes_.push_back({});
            nodes_.push_back({});
        }
    }
    auto where = [&](std::uint32_t localIndex) {
        return localIndex == 0 ? subtree.root : slots[(localIndex - 1) / 2] + (localIndex - 1) % 2;
    };
    for (std::uint32_t i = 0; i < local.size(); ++i) {
        Node node = local[i];
        if (node.count == 0) node.first = where(node.first);
        nodes_[where(i)] = node;
    }
}

bool Bvh::intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit, std::uint32_t skip) const {
    NoTraversalCount none;
    return intersectCounted(ray, tMin, tMax, hit, skip, none);
}

bool Bvh::intersect(const Ray& ray, float tMin, float tMax, HitRecord& hit, TraversalCount& count) const {
    return intersectCounted(ray, tMin, tMax, hit, kNoPrimitive, count);
}

bool Bvh::occluded(const Ray& ray, float tMin, float tMax, std::uint32_t skip) const {
    NoTraversalCount none;
    return occludedCounted(ray, tMin, tMax, skip, none);
}

bool Bvh::occluded(const Ray& ray, float tMin, float tMax, std::uint32_t skip, TraversalCount& count) const {
    return occludedCounted(ray, tMin, tMax, skip, count);
}

template <class Count>
bool Bvh::intersectCounted(const Ray& ray, float tMin, float tMax, HitRecord& hit, std::uint32_t skip,
                           Count& count) const {
    if (nodes_.empty()) return false;
    Vec3 invDir = inverseDirection(ray.direction);
    // Hidden primitives (SPEC 10.7); null in most scenes, checked once here.
    const std::uint8_t* mask = rayMask_.empty() ? nullptr : rayMask_.data();
    std::uint32_t stack[kStackSize];
    int top = 0;
    std::uint32_t current = 0;
    bool found = false;
    count.node();
    if (boxEntry(nodes_[0].bounds, ray.origin, invDir, tMin, tMax) == kInfinity) return false;
    // Once something is hit, primitives at exactly its distance are tested too
    // (up to `bound`), and the lower frame index wins the tie: the pixel must
    // not depend on the order in which this frame's tree meets them.
    float bound = tMax;
    for (;;) {
        const Node& node = nodes_[current];
        if (node.count > 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                float t;
                Face face;
                if (mask && (mask[original_[i]] & ray_mask::kHidden)) continue;
                count.primitive();
                if (original_[i] != skip && intersectPrimitive(ordered_[i], ray, tMin, bound, t, face) &&
                    (!found || t < tMax || original_[i] < hit.primitive)) {
                    tMax = t;
                    bound = nextUp(t);
                    hit = {t, original_[i], face};
                    found = true;
                }
            }
        } else {
            std::uint32_t a = node.first, b = node.first + 1;
            count.node();
            count.node();
            float ta = boxEntry(nodes_[a].bounds, ray.origin, invDir, tMin, tMax);
            float tb = boxEntry(nodes_[b].bounds, ray.origin, invDir, tMin, tMax);
            if (ta > tb) {
                std::swap(ta, tb);
                std::swap(a, b);
            }
            if (ta != kInfinity) {
                if (tb != kInfinity) stack[top++] = b;
                current = a;
                continue;
            }
        }
        // Pop the next node that can still hold something nearer.
        for (;;) {
            if (top == 0) return found;
            current = stack[--top];
            count.node();
            if (boxEntry(nodes_[current].bounds, ray.origin, invDir, tMin, tMax) != kInfinity) break;
        }
    }
}

template <class Count>
bool Bvh::occludedCounted(const Ray& ray, float tMin, float tMax, std::uint32_t skip, Count& count) const {
    if (nodes_.empty()) return false;
    Vec3 invDir = inverseDirection(ray.direction);
    // Checked once here: most scenes have no `/no_shadow` (SPEC 10.8) and
    // nothing hidden (10.7); shadow rays pass through both.
    const std::uint8_t* passThrough = rayMask_.empty() ? nullptr : rayMask_.data();
    std::uint32_t stack[kStackSize];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        count.node();
        if (boxEntry(node.bounds, ray.origin, invDir, tMin, tMax) == kInfinity) continue;
        if (node.count > 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                float t;
                Face face;
                if (original_[i] == skip || (passThrough && passThrough[original_[i]])) continue;
                count.primitive();
                if (intersectPrimitive(ordered_[i], ray, tMin, tMax, t, face)) return true;
            }
        } else {
            stack[top++] = node.first + 1;
            stack[top++] = node.first;
        }
    }
    return false;
}

}  // namespace f2
