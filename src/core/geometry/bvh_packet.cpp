// Packet traversal of the BVH: the lanes of a packet descend together, a node
// is entered when any active lane's ray crosses its box, and leaves test all
// lanes at once. Coherent rays (a 4x4 pixel block, or the parallel shadow
// rays of such a block) share almost every node, so each box and primitive
// test serves many rays.
#include "core/geometry/bvh_packet.h"

#include <algorithm>

namespace f2 {

namespace {
constexpr int kStackSize = 160;  // deeper than any tree the builder makes, plus entry nodes
// The most roots one traversal starts from: each waits on the stack, which must
// still hold a far child per level (SAH splits to depth 64, then halving to leaves).
constexpr std::size_t kMaxRoots = 48;

/// Lanes whose ray crosses the box within (tMin, tMax); as boxEntry() in bvh.cpp.
/// With a shared origin (primary rays) the differences are one scalar each.
template <class Origin, class Direction>
inline Mask crossesBox(const Bounds& b, const Rays<Origin, Direction>& r, Float tMin, Float tMax) {
    Float tx0 = (b.lo.x - r.origin.x) * r.inverseDirection.x;
    Float tx1 = (b.hi.x - r.origin.x) * r.inverseDirection.x;
    Float ty0 = (b.lo.y - r.origin.y) * r.inverseDirection.y;
    Float ty1 = (b.hi.y - r.origin.y) * r.inverseDirection.y;
    Float tz0 = (b.lo.z - r.origin.z) * r.inverseDirection.z;
    Float tz1 = (b.hi.z - r.origin.z) * r.inverseDirection.z;
    Float enter =
        simd::max(simd::max(simd::min(tx0, tx1), simd::min(ty0, ty1)), simd::max(simd::min(tz0, tz1), tMin));
    Float exit =
        simd::min(simd::min(simd::max(tx0, tx1), simd::max(ty0, ty1)), simd::min(simd::max(tz0, tz1), tMax));
    return enter <= exit;
}

/// The same for rays with one direction: which plane of each slab they meet
/// first is known once, so no lane needs a min and a max per axis.
inline Mask crossesBox(const Bounds& b, const ParallelRays& r, Float tMin, Float tMax) {
    const Vec3 inv = r.inverseDirection;
    Vec3 entry{inv.x >= 0 ? b.lo.x : b.hi.x, inv.y >= 0 ? b.lo.y : b.hi.y, inv.z >= 0 ? b.lo.z : b.hi.z};
    Vec3 exit{inv.x >= 0 ? b.hi.x : b.lo.x, inv.y >= 0 ? b.hi.y : b.lo.y, inv.z >= 0 ? b.hi.z : b.lo.z};
    Float enterX = (entry.x - r.origin.x) * inv.x, exitX = (exit.x - r.origin.x) * inv.x;
    Float enterY = (entry.y - r.origin.y) * inv.y, exitY = (exit.y - r.origin.y) * inv.y;
    Float enterZ = (entry.z - r.origin.z) * inv.z, exitZ = (exit.z - r.origin.z) * inv.z;
    // 0 * inf = NaN for an origin on the plane of a slab the rays run along:
    // min and max return their second argument then, so that slab is ignored.
    // That is only conservative: primitiveBounds() pads every box, so such an
    // origin lies outside every primitive the box holds.
    Float enter = simd::max(enterX, simd::max(enterY, simd::max(enterZ, tMin)));
    Float leave = simd::min(exitX, simd::min(exitY, simd::min(exitZ, tMax)));
    return enter <= leave;
}

/// Per axis, whether the packet's first active ray goes toward negative
/// coordinates: then the right (upper) child is visited first.
struct VisitOrder {
    bool upperFirst[3];
    template <class Origin, class Direction>
    VisitOrder(const Rays<Origin, Direction>& r, Mask active) {
        int lane = simd::firstLane(active);
        upperFirst[0] = laneOf(r.direction.x, lane) < 0;
        upperFirst[1] = laneOf(r.direction.y, lane) < 0;
        upperFirst[2] = laneOf(r.direction.z, lane) < 0;
    }
};
}  // namespace

void intersectPacket(const Bvh& bvh, const EyeRays& rays, Mask active, Float tMin, PacketHit& hit) {
    const std::uint32_t root = 0;
    intersectPacket(bvh, rays, active, tMin, hit, {&root, 1});
}

namespace {
/// The nearest-hit traversal of intersectPacket(), from `roots` and then
/// `moreRoots` (at most kMaxRoots in all); with `kSkips`, a lane does not test
/// its `skip` primitive (leaf order); with `kMasked`, hidden primitives (SPEC
/// 10.7, Bvh::rayMask) are passed by. Scenes without a mask compile the check
/// away (nearestHits picks).
template <bool kSkips, bool kMasked, class Origin, class Direction>
void nearestHitsWith(const Bvh& bvh, const Rays<Origin, Direction>& rays, Mask active, Float tMin,
                     PacketHit& hit, std::span<const std::uint32_t> roots, Int skip,
                     std::span<const std::uint32_t> moreRoots) {
    const std::span<const Bvh::Node> nodes = bvh.nodes();
    const std::span<const Primitive> ordered = bvh.orderedPrimitives();
    const std::span<const std::uint32_t> original = bvh.originalIndices();
    const std::uint8_t* mask = bvh.rayMask().data();
    if (nodes.empty() || (roots.empty() && moreRoots.empty()) || simd::none(active)) return;
    VisitOrder order(rays, active);
    Float bound = nextUp(hit.t);  // primitives are tested up to and including the lanes' nearest hit
    // The nearer child is visited next without a trip through the stack.
    std::uint32_t stack[kStackSize];
    int top = 0;
    for (std::size_t k = moreRoots.size(); k-- > 0;) stack[top++] = moreRoots[k];
    for (std::size_t k = roots.size(); k-- > 1;) stack[top++] = roots[k];  // nearest root first
    std::uint32_t current = roots.empty() ? stack[--top] : roots[0];
    for (;;) {
        const Bvh::Node& node = nodes[current];
        Mask lanes = crossesBox(node.bounds, rays, tMin, hit.t) & active;
        if (simd::any(lanes)) {
            if (node.count == 0) {
                bool upper = order.upperFirst[node.axis];
                stack[top++] = node.first + (upper ? 0 : 1);  // far child waits
                current = node.first + (upper ? 1 : 0);
                continue;
            }
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                if constexpr (kMasked) {
                    if (mask[original[i]] & ray_mask::kHidden) continue;
                }
                Mask test = lanes;
                if constexpr (kSkips) {
                    test = simd::andNot(lanes, skip == Int(std::int32_t(i)));
                    if (simd::none(test)) continue;
                }
                // As in Bvh::intersect(const Ray&): a hit at exactly a lane's
                // distance takes it when its frame index is lower.
                Float t = hit.t;
                Int face = hit.face;
                Mask found = intersectPrimitiveP(ordered[i], rays, test, tMin, bound, t, face);
                if (simd::none(found)) continue;
                Int frameIndex(static_cast<std::int32_t>(original[i]));
                Mask take = found & ((t < hit.t) | (frameIndex < hit.frameIndex));
                hit.t = simd::select(take, t, hit.t);
                hit.face = simd::select(take, face, hit.face);
                hit.primitive = simd::select(take, Int(std::int32_t(i)), hit.primitive);
                hit.frameIndex = simd::select(take, frameIndex, hit.frameIndex);
                bound = nextUp(hit.t);
            }
        }
        if (top == 0) return;
        current = stack[--top];
    }
}

template <bool kSkips, class Origin, class Direction>
void nearestHits(const Bvh& bvh, const Rays<Origin, Direction>& rays, Mask active, Float tMin, PacketHit& hit,
                 std::span<const std::uint32_t> roots, Int skip,
                 std::span<const std::uint32_t> moreRoots = {}) {
    if (bvh.rayMask().empty())
        nearestHitsWith<kSkips, false>(bvh, rays, active, tMin, hit, roots, skip, moreRoots);
    else
        nearestHitsWith<kSkips, true>(bvh, rays, active, tMin, hit, roots, skip, moreRoots);
}
}  // namespace

void intersectPacket(const Bvh& bvh, const EyeRays& rays, Mask active, Float tMin, PacketHit& hit,
                     std::span<const std::uint32_t> roots) {
    nearestHits<false>(bvh, rays, active, tMin, hit, roots, Int(-1));
}

void intersectPacket(const Bvh& bvh, const EyeRays& rays, Mask active, Float tMin, PacketHit& hit,
                     std::span<const std::uint32_t> roots, std::span<const std::uint32_t> moreRoots) {
    // Long lists in parts that leave room on the traversal's stack.
    while (roots.size() + moreRoots.size() > kMaxRoots) {
        std::span<const std::uint32_t>& longer = roots.size() >= moreRoots.size() ? roots : moreRoots;
        const std::size_t part = std::min(longer.size(), kMaxRoots);
        nearestHits<false>(bvh, rays, active, tMin, hit, longer.first(part), Int(-1));
        longer = longer.subspan(part);
    }
    nearestHits<false>(bvh, rays, active, tMin, hit, roots, Int(-1), moreRoots);
}

void intersectPacket(const Bvh& bvh, const FreeRays& rays, Mask active, Float tMin, PacketHit& hit,
                     Int skip) {
    const std::uint32_t root = 0;
    nearestHits<true>(bvh, rays, active, tMin, hit, {&root, 1}, skip);
}

Mask occludedPacket(const Bvh& bvh, const ParallelRays& rays, Mask active, Float tMin, Float tMax, Int skip) {
    const std::uint32_t root = 0;
    return occludedPacket(bvh, rays, active, tMin, tMax, skip, {&root, 1});
}

namespace {
/// The any-hit traversal of occludedPacket(); with `kMasked`, primitives
/// with a ray_mask flag (`/no_shadow`, hidden) are passed by.
template <bool kMasked, class Origin, class Direction>
Mask occludedFromWith(const Bvh& bvh, const Rays<Origin, Direction>& rays, Mask active, Float tMin,
                      Float tMax, Int skip, std::span<const std::uint32_t> roots) {
    const std::span<const Bvh::Node> nodes = bvh.nodes();
    const std::span<const Primitive> ordered = bvh.orderedPrimitives();
    const std::uint8_t* passThrough = bvh.rayMask().data();
    const std::span<const std::uint32_t> frameIndex = bvh.originalIndices();
    Mask blocked = simd::noLanes();
    if (nodes.empty() || roots.empty() || simd::none(active)) return blocked;
    VisitOrder order(rays, active);  // the nearer occluder first ends a lane sooner
    std::uint32_t stack[kStackSize];
    int top = 0;
    for (std::size_t k = roots.size(); k-- > 1;) stack[top++] = roots[k];
    std::uint32_t current = roots[0];
    for (;;) {
        const Bvh::Node& node = nodes[current];
        Mask pending = simd::andNot(active, blocked);
        Mask lanes = crossesBox(node.bounds, rays, tMin, tMax) & pending;
        if (simd::any(lanes)) {
            if (node.count == 0) {
                bool upper = order.upperFirst[node.axis];
                stack[top++] = node.first + (upper ? 0 : 1);
                current = node.first + (upper ? 1 : 0);
                continue;
            }
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                if constexpr (kMasked) {
                    if (passThrough[frameIndex[i]]) continue;
                }
                Mask test = simd::andNot(lanes, skip == Int(std::int32_t(i)));
                if (simd::none(test)) continue;
                Float t = tMax;
                Int face;
                blocked = blocked | intersectPrimitiveP(ordered[i], rays, test, tMin, tMax, t, face);
                lanes = simd::andNot(lanes, blocked);
                if (simd::none(lanes)) break;
            }
            if (simd::none(simd::andNot(active, blocked))) return blocked;  // every ray is in shadow
        }
        if (top == 0) return blocked;
        current = stack[--top];
    }
}

template <class Origin, class Direction>
Mask occludedFrom(const Bvh& bvh, const Rays<Origin, Direction>& rays, Mask active, Float tMin, Float tMax,
                  Int skip, std::span<const std::uint32_t> roots) {
    // Most scenes have no `/no_shadow` and nothing hidden, and pay nothing for them.
    if (bvh.rayMask().empty()) return occludedFromWith<false>(bvh, rays, active, tMin, tMax, skip, roots);
    return occludedFromWith<true>(bvh, rays, active, tMin, tMax, skip, roots);
}
}  // namespace

Mask occludedPacket(const Bvh& bvh, const ParallelRays& rays, Mask active, Float tMin, Float tMax, Int skip,
                    std::span<const std::uint32_t> roots) {
    return occludedFrom(bvh, rays, active, tMin, tMax, skip, roots);
}

Mask occludedPacket(const Bvh& bvh, const EyeRays& rays, Mask active, Float tMin, Float tMax, Int skip) {
    const std::uint32_t root = 0;
    return occludedFrom(bvh, rays, active, tMin, tMax, skip, {&root, 1});
}

Mask occludedPacket(const Bvh& bvh, const FreeRays& rays, Mask active, Float tMin, Float tMax, Int skip) {
    const std::uint32_t root = 0;
    return occludedFrom(bvh, rays, active, tMin, tMax, skip, {&root, 1});
}

template <class Excludes, class Distance>
std::size_t Bvh::entryNodesWhere(const Excludes& excludes, const Distance& distance,
                                 std::span<std::uint32_t> out) const {
    if (nodes_.empty() || out.empty() || excludes(nodes_[0].bounds)) return 0;
    std::size_t count = 1;
    out[0] = 0;
    for (;;) {
        // The inner node with the largest box is the one most packets would enter.
        std::size_t widest = count;
        float widestArea = -1;
        for (std::size_t k = 0; k < count; ++k) {
            const Node& node = nodes_[out[k]];
            if (node.count == 0 && node.bounds.halfArea() > widestArea) {
                widest = k;
                widestArea = node.bounds.halfArea();
            }
        }
        if (widest == count) break;  // only leaves left
        const Node& node = nodes_[out[widest]];
        std::uint32_t kept[2];
        std::size_t keptCount = 0;
        for (std::uint32_t child : {node.first, node.first + 1})
            if (!excludes(nodes_[child].bounds)) kept[keptCount++] = child;
        if (count - 1 + keptCount > out.size()) break;
        if (keptCount == 0) {
            out[widest] = out[--count];  // nothing of it is reachable
            if (count == 0) return 0;
        } else {
            out[widest] = kept[0];
            if (keptCount == 2) out[count++] = kept[1];
        }
    }
    std::sort(out.begin(), out.begin() + std::ptrdiff_t(count), [&](std::uint32_t a, std::uint32_t b) {
        return distance(nodes_[a].bounds) < distance(nodes_[b].bounds);
    });
    return count;
}

std::size_t Bvh::entryNodes(const Frustum& frustum, Vec3 eye, std::span<std::uint32_t> out) const {
    // Nearest first, by the distance from the eye to each box.
    return entryNodesWhere([&](const Bounds& b) { return frustum.excludes(b); },
                           [&](const Bounds& b) {
                               Vec3 d = vmin(vmax(eye, b.lo), b.hi) - eye;
                               return dot(d, d);
                           },
                           out);
}

namespace {
/// Whether no ray o + t d (o in `origins`, t >= 0) meets a box: the one ray
/// t d from 0 must miss B - origins = [B.lo - origins.hi, B.hi - origins.lo],
/// here widened by `slack` against the rounding of that arithmetic.
struct BeamMisses {
    const Bounds& origins;
    float slack;
    explicit BeamMisses(const Bounds& o) : origins(o) {
        Vec3 magnitude = vmax(vmax(o.lo, -o.lo), vmax(o.hi, -o.hi));
        slack = 1e-5f * (1.0f + std::max({magnitude.x, magnitude.y, magnitude.z}));
    }
    bool operator()(const Bounds& b, Vec3 direction) const {
        float enter = 0, exit = kInfinity;
        for (int i = 0; i < 3; ++i) {
            float lo = b.lo[i] - origins.hi[i] - slack, hi = b.hi[i] - origins.lo[i] + slack;
            if (direction[i] == 0) {
                if (lo > 0 || hi < 0) return true;
                continue;
            }
            float t0 = lo / direction[i], t1 = hi / direction[i];
            enter = std::max(enter, std::min(t0, t1));
            exit = std::min(exit, std::max(t0, t1));
        }
        return enter > exit;
    }
};
}  // namespace

std::size_t Bvh::beamEntryNodes(const Bounds& origins, Vec3 direction, std::span<std::uint32_t> out) const {
    const BeamMisses misses(origins);
    // Nearest first along the rays, where an occluder ends them soonest.
    return entryNodesWhere([&](const Bounds& b) { return misses(b, direction); },
                           [&](const Bounds& b) { return dot(b.centroid(), direction); }, out);
}

std::size_t Bvh::beamEntryNodes(const Bounds& origins, std::span<const Vec3> directions,
                                std::span<std::uint32_t> out) const {
    if (directions.empty()) return 0;
    const BeamMisses misses(origins);
    const Vec3 first = directions.front();
    return entryNodesWhere(
        [&](const Bounds& b) {
            return std::all_of(directions.begin(), directions.end(), [&](Vec3 d) { return misses(b, d); });
        },
        [&](const Bounds& b) { return dot(b.centroid(), first); }, out);
}

}  // namespace f2
