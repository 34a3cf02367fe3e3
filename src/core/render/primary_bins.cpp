#include "core/render/primary_bins.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/packet.h"

namespace f2 {

namespace {
/// Bound on the relative rounding of the projection (a few float ulps, times ten).
constexpr float kRelativeError = 1e-5f;
/// Subtrees the top of the tree is split into, to be walked on the pool.
constexpr std::size_t kParallelWalks = 32;
/// Footprint coordinates are 16 bits.
constexpr std::size_t kMaxCells = 0xFFFF;

}  // namespace

void PrimaryBins::projectBatch(std::span<const Bvh::Node> nodes, const std::uint32_t* indices,
                               std::size_t count, Projection* out) const {
    // Camera coordinates c = R^T (p - eye); the ray through image point (px, py)
    // has c.x / c.z = u and c.y / c.z = v with px = width / 2 + u * scaleX and
    // py = height / 2 - v * scaleY (Camera::rayThrough, Camera::project).
    // simd::kWidth boxes at a time (the last repeated to fill the lanes).
    const View& w = view_;
    alignas(64) float lo[3][simd::kWidth], hi[3][simd::kWidth];
    for (std::size_t i = 0; i < std::size_t(simd::kWidth); ++i) {
        const Bounds& b = nodes[indices[std::min(i, count - 1)]].bounds;
        for (int a = 0; a < 3; ++a) {
            lo[a][i] = b.lo[a];
            hi[a][i] = b.hi[a];
        }
    }
    const Vec3P boxLo(simd::load(lo[0]), simd::load(lo[1]), simd::load(lo[2]));
    const Vec3P boxHi(simd::load(hi[0]), simd::load(hi[1]), simd::load(hi[2]));
    // The box in camera space: centre c, half extents e along the camera's axes.
    const Float one(1.0f), zero(0.0f), halfOf(0.5f);
    const Vec3P centre = boxLo * halfOf + boxHi * halfOf, half = boxHi * halfOf - boxLo * halfOf;
    const Vec3P rel = centre - w.eye;
    const Vec3P c(dot(rel, w.right), dot(rel, w.up), dot(rel, w.forward));
    const Vec3P ac(simd::abs(c.x), simd::abs(c.y), simd::abs(c.z));
    // Padded for the rounding of the centre, the half extents and the rotation.
    auto largest = [](const Vec3P& v) { return simd::max(v.x, simd::max(v.y, v.z)); };
    const Float pad =
        Float(2e-6f) * (largest(Vec3P(simd::abs(centre.x), simd::abs(centre.y), simd::abs(centre.z))) +
                        largest(half) + ac.x + ac.y + ac.z);
    const Vec3P e(dot(half, w.absRight) + pad, dot(half, w.absUp) + pad, dot(half, w.absForward) + pad);
    const Float check = c.x + c.y + c.z + e.x + e.y + e.z;
    const Mask finite = (check - check) == zero;  // no infinity, no NaN
    const Float zLo = c.z - e.z, zHi = c.z + e.z;
    const Mask behind = zHi < zero;  // no primary ray goes backwards
    const Mask front = zLo > zero;
    // Over the box [c - e, c + e] in front of the eye, x / z and y / z are extreme at corners.
    const Float nearInverse = one / zLo, farInverse = one / zHi;
    const Float xLo = c.x - e.x, xHi = c.x + e.x, yLo = c.y - e.y, yHi = c.y + e.y;
    const Float uLo = simd::min(xLo * nearInverse, xLo * farInverse);
    const Float uHi = simd::max(xHi * nearInverse, xHi * farInverse);
    const Float vLo = simd::min(yLo * nearInverse, yLo * farInverse);
    const Float vHi = simd::max(yHi * nearInverse, yHi * farInverse);
    // Their rounding, and that of the rays' directions, grows with |u|, |v| and 1 / z.
    const Float sum = (ac.x + ac.y + ac.z + e.x + e.y + e.z) * nearInverse;
    const Float error = Float(kRelativeError) * sum * (one + sum);
    const Float width(w.width), height(w.height), margin(w.margin);
    const Float pxLo = Float(0.5f) * width + (uLo - error) * Float(w.scaleX) - margin;
    const Float pxHi = Float(0.5f) * width + (uHi + error) * Float(w.scaleX) + margin;
    const Float pyLo = Float(0.5f) * height - (vHi + error) * Float(w.scaleY) - margin;
    const Float pyHi = Float(0.5f) * height - (vLo - error) * Float(w.scaleY) + margin;
    const Mask bounded = (pxLo <= pxHi) & (pyLo <= pyHi);  // no NaN after an overflow
    const Mask offImage = (pxHi < zero) | (pyHi < zero) | (pxLo > width) | (pyLo > height);
    alignas(64) float x0[simd::kWidth], x1[simd::kWidth], y0[simd::kWidth], y1[simd::kWidth];
    simd::store(x0, simd::max(zero, simd::floor(pxLo * Float(1.0f / float(kCellWidth)))));
    simd::store(x1,
                simd::min(Float(float(cellsX_ - 1)), simd::floor(pxHi * Float(1.0f / float(kCellWidth)))));
    simd::store(y0, simd::max(zero, simd::floor(pyLo * Float(1.0f / float(kCellHeight)))));
    simd::store(y1,
                simd::min(Float(float(cellsY_ - 1)), simd::floor(pyHi * Float(1.0f / float(kCellHeight)))));
    const std::uint32_t notFinite = ~simd::bits(finite), isBehind = simd::bits(behind),
                        inFront = simd::bits(front), isBounded = simd::bits(bounded),
                        isOff = simd::bits(offImage);
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t bit = 1u << i;
        Projection& p = out[i];
        p = {};
        if (notFinite & bit)
            p.kind = Projection::NotFinite;
        else if (isBehind & bit)
            p.kind = Projection::Behind;
        else if (!(inFront & bit) || !(isBounded & bit))
            p.kind = Projection::AtEyePlane;
        else if (isOff & bit)
            p.kind = Projection::OffImage;
        else {
            p.kind = Projection::OnImage;
            p.footprint = {std::uint16_t(x0[i]), std::uint16_t(y0[i]), std::uint16_t(x1[i]),
                           std::uint16_t(y1[i])};
            p.cells = std::uint64_t(x1[i] - x0[i] + 1) * std::uint64_t(y1[i] - y0[i] + 1);
        }
    }
}

void PrimaryBins::descend(std::span<const Bvh::Node> nodes, Walk& walk, std::size_t stopAt) const {
    Projection projection[simd::kWidth];
    std::uint32_t batch[simd::kWidth];
    bool split[simd::kWidth];
    std::vector<std::uint32_t>& stack = walk.stack;
    while (!stack.empty() && stack.size() < stopAt) {
        // The nodes on top of the stack, projected together.
        const std::size_t count = std::min(stack.size(), std::size_t(simd::kWidth));
        std::copy(stack.end() - std::ptrdiff_t(count), stack.end(), batch);
        stack.resize(stack.size() - count);
        projectBatch(nodes, batch, count, projection);
        for (std::size_t k = count; k-- > 0;) {  // listed nearest first, as they were stacked
            const std::uint32_t index = batch[k];
            const Bvh::Node& node = nodes[index];
            const bool leaf = node.count > 0;
            const Projection& p = projection[k];
            split[k] = false;
            switch (p.kind) {
                case Projection::NotFinite:
                    walk.finite = false;
                    return;
                case Projection::Behind:
                case Projection::OffImage:
                    break;  // no primary ray reaches it
                case Projection::AtEyePlane:
                    if (view_.frustum.excludes(node.bounds)) break;
                    if (leaf) walk.everywhere.push_back(index);
                    split[k] = !leaf;
                    break;
                case Projection::OnImage:
                    if (p.cells >
                        view_.wide) {  // cheaper walked by every packet than listed in a quarter of the cells
                        if (leaf) walk.everywhere.push_back(index);
                        split[k] = !leaf;
                    } else if (leaf || p.cells <= kCutCells) {
                        walk.cut.push_back({p.footprint, index});
                    } else {
                        split[k] = true;
                    }
                    break;
            }
        }
        for (std::size_t k = 0; k < count; ++k) {  // the children of the nearest end on top
            if (!split[k]) continue;
            const Bvh::Node& node = nodes[batch[k]];
            const bool upper = view_.upperFirst[node.axis];  // the nearer child on top
            stack.push_back(node.first + (upper ? 0 : 1));
            stack.push_back(node.first + (upper ? 1 : 0));
        }
    }
}

bool PrimaryBins::cutTree(std::span<const Bvh::Node> nodes, ThreadPool* pool) {
    cut_.clear();
    everywhere_.clear();
    if (nodes.empty()) return true;
    // The top of the tree here, until there are enough subtrees to share out.
    Walk& top = top_;
    top.cut.clear();
    top.everywhere.clear();
    top.stack.assign(1, 0);
    top.finite = true;
    descend(nodes, top, pool ? kParallelWalks : std::numeric_limits<std::size_t>::max());
    if (!top.finite) return false;
    // Below, the subtrees left on the stack, each walked on its own (the nearest, on top, first).
    const std::size_t count = top.stack.size();
    if (walks_.size() < count) walks_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        Walk& walk = walks_[i];
        walk.cut.clear();
        walk.everywhere.clear();
        walk.stack.assign(1, top.stack[count - 1 - i]);
        walk.finite = true;
    }
    if (count > 0)
        pool->parallelFor(std::uint32_t(count), [&](std::uint32_t i) {
            descend(nodes, walks_[i], std::numeric_limits<std::size_t>::max());
        });
    cut_.insert(cut_.end(), top.cut.begin(), top.cut.end());
    everywhere_.insert(everywhere_.end(), top.everywhere.begin(), top.everywhere.end());
    for (std::size_t i = 0; i < count; ++i) {
        const Walk& walk = walks_[i];
        if (!walk.finite) return false;
        cut_.insert(cut_.end(), walk.cut.begin(), walk.cut.end());
        everywhere_.insert(everywhere_.end(), walk.everywhere.begin(), walk.everywhere.end());
    }
    return true;
}

void PrimaryBins::build(const Bvh& bvh, const Camera& camera, ThreadPool* pool, std::size_t minPrimitives,
                        float marginPixels) {
    active_ = false;
    const std::size_t primitives = bvh.orderedPrimitives().size();
    if (primitives == 0 || primitives < minPrimitives || camera.width < 1 || camera.height < 1 ||
        !(camera.distance > 0))
        return;
    cellsX_ = (std::size_t(camera.width) + kCellWidth - 1) / kCellWidth;
    cellsY_ = (std::size_t(camera.height) + kCellHeight - 1) / kCellHeight;
    if (cellsX_ > kMaxCells || cellsY_ > kMaxCells) return;
    const std::size_t cells = cellsX_ * cellsY_;
    const Mat3& r = camera.worldFromCamera;
    const Vec3 forward = r.column(2);
    view_ = {camera.eye,
             r.column(0),
             r.column(1),
             forward,
             vabs(r.column(0)),
             vabs(r.column(1)),
             vabs(forward),
             {forward.x < 0, forward.y < 0, forward.z < 0},
             float(camera.width),
             float(camera.height),
             camera.distance * float(camera.width),
             camera.distance / camera.aspect() * float(camera.height),
             marginPixels,
             camera.pixelFrustum(0, 0, camera.width, camera.height),
             std::uint64_t(cellsX_) * cellsY_ / 4};

    // 1. The cut: nodes that cover few cells, from the root down.
    if (!cutTree(bvh.nodes(), pool) || everywhere_.size() > kMaxEverywhere) return;
    std::uint64_t entries = 0;
    for (const Listed& listed : cut_)
        entries += std::uint64_t(listed.footprint.x1 - listed.footprint.x0 + 1) *
                   std::uint64_t(listed.footprint.y1 - listed.footprint.y0 + 1);
    if (entries > kMaxMeanCandidates * cells) return;

    // 2. Into the cells, in the cut's order (counting sort by cell).
    cellStart_.assign(cells + 1, 0);
    for (const Listed& listed : cut_) {
        const Footprint& f = listed.footprint;
        for (std::size_t y = f.y0; y <= f.y1; ++y)
            for (std::size_t x = f.x0; x <= f.x1; ++x) ++cellStart_[y * cellsX_ + x + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) cellStart_[c + 1] += cellStart_[c];
    entries_.resize(entries);
    for (const Listed& listed : cut_) {
        const Footprint& f = listed.footprint;
        for (std::size_t y = f.y0; y <= f.y1; ++y)
            for (std::size_t x = f.x0; x <= f.x1; ++x) entries_[cellStart_[y * cellsX_ + x]++] = listed.node;
    }
    // cellStart_[c] now holds the end of cell c, which is where c + 1 starts.
    for (std::size_t c = cells; c > 0; --c) cellStart_[c] = cellStart_[c - 1];
    cellStart_[0] = 0;
    active_ = true;
}

}  // namespace f2
