// Packet traversal of the BVH: the lanes of a packet descend together, a node
// is entered when any active lane's ray crosses its box, and leaves test all
// lanes at once. Coherent rays (a 4x4 pixel block, or the parallel shadow
// rays of such a block) share almost every node, so each box and primitive
// test serves many rays.
#include "core/geometry/bvh.h"

namespace f2 {

namespace {
constexpr int kStackSize = 128;  // deeper than any tree the builder makes

/// Lanes whose ray crosses the box within (tMin, tMax); as boxEntry() in bvh.cpp.
inline Mask crossesBox(const Bounds& b, const RayPacket& r, Float tMin, Float tMax) {
    Float tx0 = (Float(b.lo.x) - r.origin.x) * r.inverseDirection.x;
    Float tx1 = (Float(b.hi.x) - r.origin.x) * r.inverseDirection.x;
    Float ty0 = (Float(b.lo.y) - r.origin.y) * r.inverseDirection.y;
    Float ty1 = (Float(b.hi.y) - r.origin.y) * r.inverseDirection.y;
    Float tz0 = (Float(b.lo.z) - r.origin.z) * r.inverseDirection.z;
    Float tz1 = (Float(b.hi.z) - r.origin.z) * r.inverseDirection.z;
    Float enter = simd::max(simd::max(simd::min(tx0, tx1), simd::min(ty0, ty1)), simd::max(simd::min(tz0, tz1), tMin));
    Float exit = simd::min(simd::min(simd::max(tx0, tx1), simd::max(ty0, ty1)), simd::min(simd::max(tz0, tz1), tMax));
    return enter <= exit;
}

/// Per axis, whether the packet's first active ray goes toward negative
/// coordinates: then the right (upper) child is visited first.
struct VisitOrder {
    bool upperFirst[3];
    VisitOrder(const RayPacket& r, Mask active) {
        int lane = simd::firstLane(active);
        upperFirst[0] = simd::lane(r.direction.x, lane) < 0;
        upperFirst[1] = simd::lane(r.direction.y, lane) < 0;
        upperFirst[2] = simd::lane(r.direction.z, lane) < 0;
    }
};
}  // namespace

void Bvh::intersect(const RayPacket& rays, Mask active, Float tMin, PacketHit& hit) const {
    if (nodes_.empty() || simd::none(active)) return;
    VisitOrder order(rays, active);
    // The nearer child is visited next without a trip through the stack.
    std::uint32_t stack[kStackSize];
    int top = 0;
    std::uint32_t current = 0;
    for (;;) {
        const Node& node = nodes_[current];
        Mask lanes = crossesBox(node.bounds, rays, tMin, hit.t) & active;
        if (simd::any(lanes)) {
            if (node.count == 0) {
                bool upper = order.upperFirst[node.axis];
                stack[top++] = node.first + (upper ? 0 : 1);  // far child waits
                current = node.first + (upper ? 1 : 0);
                continue;
            }
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                Mask hitLanes = intersectPrimitiveP(ordered_[i], rays, lanes, tMin, hit.t, hit.t, hit.face);
                hit.primitive = simd::select(hitLanes, Int(std::int32_t(i)), hit.primitive);
            }
        }
        if (top == 0) return;
        current = stack[--top];
    }
}

Mask Bvh::occluded(const RayPacket& rays, Mask active, Float tMin, Float tMax, Int skip) const {
    Mask blocked = simd::noLanes();
    if (nodes_.empty() || simd::none(active)) return blocked;
    VisitOrder order(rays, active);  // the nearer occluder first ends a lane sooner
    std::uint32_t stack[kStackSize];
    int top = 0;
    std::uint32_t current = 0;
    for (;;) {
        const Node& node = nodes_[current];
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
                Mask test = simd::andNot(lanes, skip == Int(std::int32_t(i)));
                if (simd::none(test)) continue;
                Float t = tMax;
                Int face;
                blocked = blocked | intersectPrimitiveP(ordered_[i], rays, test, tMin, tMax, t, face);
                lanes = simd::andNot(lanes, blocked);
                if (simd::none(lanes)) break;
            }
            if (simd::none(simd::andNot(active, blocked))) return blocked;  // every ray is in shadow
        }
        if (top == 0) return blocked;
        current = stack[--top];
    }
}

}  // namespace f2
