#pragma once
/// The beam of one packet's shadow rays toward a soft sun: every ray from
/// the packet's origins toward any of the sun's sample directions. Before
/// its samples are traced one by one, the tile's entry nodes are narrowed to
/// the nodes this beam may reach, once for all samples. Private to the core
/// (SIMD types).
#include <algorithm>
#include <span>

#include "core/geometry/bvh.h"
#include "core/geometry/packet.h"

namespace f2 {

/// Directions bounded component by component (a soft sun's samples).
struct DirectionBox {
    Vec3 lo{kInfinity, kInfinity, kInfinity}, hi{-kInfinity, -kInfinity, -kInfinity};
};

/// What a tile knows of the shadow rays toward one light: the BVH nodes they
/// start from (Bvh::beamEntryNodes of the tile's origins), and for a soft
/// sun the box of its sample directions and a margin against rounding.
struct LightEntry {
    std::span<const std::uint32_t> nodes;
    DirectionBox directions;
    float slack = 0;
};

/// The margin of BeamTest against the rounding of its arithmetic (and of the
/// traversal's box tests): relative to the largest coordinate of the scene.
inline float beamSlack(const Bvh& bvh) {
    if (bvh.nodes().empty()) return 0;
    const Bounds& b = bvh.nodes()[0].bounds;
    const Vec3 m = vmax(vmax(b.lo, -b.lo), vmax(b.hi, -b.hi));
    return 1e-4f * (1.0f + std::max({m.x, m.y, m.z}));
}

/// Whether some ray o + t d (o a lane's origin, d in the box of directions,
/// t >= 0) may come within the beam's slack of a box. Per axis the ray's
/// coordinate lies in [o + t d.lo, o + t d.hi] (t >= 0), which must meet the
/// box's widened interval; a lane is out only if no t serves all three axes.
/// The bounds on t are products with reciprocals (one rounding more than a
/// division), which the slack, far larger, covers.
class BeamTest {
   public:
    BeamTest(const DirectionBox& d, float slack) : slack_(slack) {
        for (int i = 0; i < 3; ++i) {
            hi_[i] = d.hi[i], lo_[i] = d.lo[i];
            inverseHi_[i] = 1.0f / d.hi[i];
            inverseLo_[i] = 1.0f / -d.lo[i];
        }
    }
    /// Whether any `active` lane's beam from `origin` may reach `box`.
    bool mayReach(const Bounds& box, const Vec3P& origin, Mask active) const {
        Float lower(0.0f), upper(kInfinity);
        Mask out = simd::noLanes();
        for (int i = 0; i < 3; ++i) {
            const Float o = component(origin, i);
            // The coordinate reaches the box's low side: (o - lo + slack) + t d.hi >= 0.
            const Float a = o - Float(box.lo[i] - slack_);
            if (hi_[i] > 0)
                lower = simd::max(lower, -a * Float(inverseHi_[i]));
            else if (hi_[i] < 0)
                upper = simd::min(upper, a * Float(-inverseHi_[i]));
            else
                out = out | (a < Float(0.0f));
            // And stays below its high side: (hi + slack - o) - t d.lo >= 0.
            const Float b = Float(box.hi[i] + slack_) - o;
            if (lo_[i] < 0)
                lower = simd::max(lower, -b * Float(inverseLo_[i]));
            else if (lo_[i] > 0)
                upper = simd::min(upper, b * Float(-inverseLo_[i]));
            else
                out = out | (b < Float(0.0f));
        }
        return simd::any(simd::andNot(active & (lower <= upper), out));
    }

   private:
    float hi_[3], lo_[3], inverseHi_[3], inverseLo_[3];
    float slack_;
};

/// The nodes at or below `light.nodes` that the shadow rays of the `active`
/// lanes (origins `origin`, each skipping its own primitive `skip`) toward
/// the directions of `light` may reach, into `out`: nodes their beam misses
/// are left out, inner nodes are replaced by their children while `budget`
/// node tests last, and a leaf whose one primitive every ray skips is left
/// out. Returns how many, or out.size() + 1 if they do not fit (then the
/// caller keeps light.nodes). Any-hit answers do not depend on where the
/// traversal starts, as long as no reachable primitive is left out.
inline std::size_t packetEntryNodes(const Bvh& bvh, const LightEntry& light, const Vec3P& origin, Mask active,
                                    Int skip, std::span<std::uint32_t> out, int budget = 32) {
    const std::span<const Bvh::Node> nodes = bvh.nodes();
    const BeamTest beam(light.directions, light.slack);
    // The one primitive every active lane skips, if they share one.
    alignas(64) std::int32_t skips[simd::kWidth];
    simd::store(skips, skip);
    const std::int32_t shared = skips[simd::firstLane(active)];
    const bool allSkip = simd::none(simd::andNot(active, skip == Int(shared)));

    constexpr int kStack = 64;
    std::uint32_t stack[kStack];
    int top = 0;
    for (std::size_t k = light.nodes.size(); k-- > 0;) stack[top++] = light.nodes[k];
    std::size_t count = 0;
    while (top > 0) {
        const std::uint32_t index = stack[--top];
        const Bvh::Node& node = nodes[index];
        if (budget-- > 0) {
            if (!beam.mayReach(node.bounds, origin, active)) continue;
            if (node.count == 1 && allSkip && std::int32_t(node.first) == shared) continue;
            if (node.count == 0 && top + 2 <= kStack) {
                stack[top++] = node.first + 1;
                stack[top++] = node.first;  // the left child first, as the tile's order
                continue;
            }
        }
        if (count == out.size()) return out.size() + 1;
        out[count++] = index;
    }
    return count;
}

}  // namespace f2
