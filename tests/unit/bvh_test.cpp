// Bvh against brute force: the tree must return exactly what testing every
// primitive returns (nearest hit and any-hit), for random scenes and for the
// degenerate layouts a per-frame rebuild can meet (empty, one primitive,
// coincident primitives, an exponentially stretched line).
#include "core/geometry/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <utility>
#include <vector>

#include "core/geometry/bvh_packet.h"
#include "core/render/camera.h"
#include "test_scenes.h"

namespace f2 {
namespace {

struct Brute {
    bool found = false;
    float t = kInfinity;
    std::uint32_t primitive = 0;
};

/// Nearest hit by testing every primitive with the caller's (tMin, tMax).
Brute bruteNearest(const std::vector<Primitive>& prims, const Ray& ray, float tMin, float tMax) {
    Brute b;
    for (std::uint32_t i = 0; i < prims.size(); ++i) {
        float t;
        Face face;
        if (intersectPrimitive(prims[i], ray, tMin, tMax, t, face) && t < b.t) b = {true, t, i};
    }
    return b;
}

bool bruteAny(const std::vector<Primitive>& prims, const Ray& ray, float tMin, float tMax) {
    for (const Primitive& p : prims) {
        float t;
        Face face;
        if (intersectPrimitive(p, ray, tMin, tMax, t, face)) return true;
    }
    return false;
}

/// Depth of the deepest leaf (root = 1) and the number of primitives in leaves;
/// also checks that each inner node's box contains its children's boxes.
std::pair<int, std::uint64_t> inspectTree(const Bvh& bvh) {
    auto nodes = bvh.nodes();
    int maxDepth = 0;
    std::uint64_t leafPrims = 0;
    if (nodes.empty()) return {0, 0};
    std::vector<std::pair<std::uint32_t, int>> stack{{0u, 1}};
    while (!stack.empty()) {
        auto [i, depth] = stack.back();
        stack.pop_back();
        EXPECT_LT(i, nodes.size());
        if (i >= nodes.size()) break;
        maxDepth = std::max(maxDepth, depth);
        const Bvh::Node& n = nodes[i];
        if (n.count > 0) {
            leafPrims += n.count;
            continue;
        }
        for (std::uint32_t c : {n.first, n.first + 1}) {
            EXPECT_LT(c, nodes.size());
            if (c >= nodes.size()) continue;
            const Bounds& b = nodes[c].bounds;
            for (int a = 0; a < 3; ++a) {
                EXPECT_LE(n.bounds.lo[a], b.lo[a]);
                EXPECT_GE(n.bounds.hi[a], b.hi[a]);
            }
            stack.push_back({c, depth + 1});
        }
    }
    return {maxDepth, leafPrims};
}

/// Compares one ray's Bvh::intersect with brute force; true when they agree.
::testing::AssertionResult agrees(const std::vector<Primitive>& prims, const Bvh& bvh, const Ray& ray,
                                  float tMin, float tMax) {
    Brute b = bruteNearest(prims, ray, tMin, tMax);
    HitRecord hit;
    bool found = bvh.intersect(ray, tMin, tMax, hit);
    auto describe = [&] {
        return ::testing::Message() << " ray " << ray.origin << " dir " << ray.direction << " tMin " << tMin
                                    << " tMax " << tMax << "; brute " << b.found << " prim " << b.primitive
                                    << " t " << b.t << "; bvh " << found << " prim " << hit.primitive << " t "
                                    << hit.t;
    };
    if (found != b.found) return ::testing::AssertionFailure() << "hit/miss differs" << describe();
    if (!found) return ::testing::AssertionSuccess();
    if (std::fabs(hit.t - b.t) > 1e-4f * std::max(1.0f, b.t))
        return ::testing::AssertionFailure() << "distance differs" << describe();
    if (hit.primitive != b.primitive) {
        // Only a genuine tie may pick another primitive: the BVH's one must be hit at the same t.
        float t;
        Face face;
        if (hit.primitive >= prims.size() ||
            !intersectPrimitive(prims[hit.primitive], ray, tMin, tMax, t, face) || t != b.t)
            return ::testing::AssertionFailure() << "primitive differs" << describe();
    }
    if (!(hit.t > tMin && hit.t < tMax))
        return ::testing::AssertionFailure() << "t out of range" << describe();
    return ::testing::AssertionSuccess();
}

std::vector<Primitive> randomScene(std::mt19937& rng, int count, float spread) {
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), angle(-180.0f, 180.0f), coord(-spread, spread);
    auto dim = [&] { return 0.5f + 14.5f * u01(rng); };
    std::vector<Primitive> prims;
    for (int i = 0; i < count; ++i) {
        ShapeKind kind = ShapeKind(int(u01(rng) * 3) % 3);
        Vec3 size = kind == ShapeKind::Sphere     ? Vec3{dim(), 0, 0}
                    : kind == ShapeKind::Cylinder ? Vec3{dim(), 2 * dim(), 0}
                                                  : Vec3{2 * dim(), 2 * dim(), 2 * dim()};
        // A fifth of them unrotated, so axis-aligned faces meet axis-aligned rays.
        Vec3 rot = u01(rng) < 0.2f ? Vec3{} : Vec3{angle(rng), angle(rng), angle(rng)};
        prims.push_back(
            makePrimitive(kind, size, Transform::fromPose({coord(rng), coord(rng), coord(rng)}, rot)));
    }
    return prims;
}

Vec3 randomUnit(std::mt19937& rng) {
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    float z = 2 * u01(rng) - 1, phi = float(2 * kPi) * u01(rng), s = std::sqrt(std::max(0.0f, 1 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

/// Random rays over the scene: half aimed at a primitive's centre (so many hit),
/// a tenth along a coordinate axis (infinite inverse components in the slab test).
Ray randomRay(std::mt19937& rng, const std::vector<Primitive>& prims, float spread) {
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), coord(-1.5f * spread, 1.5f * spread);
    Vec3 origin{coord(rng), coord(rng), coord(rng)};
    float kind = u01(rng);
    Vec3 dir;
    if (kind < 0.5f && !prims.empty()) {
        Vec3 target = prims[std::size_t(u01(rng) * prims.size()) % prims.size()].centre;
        dir = normalize(target - origin);
    } else if (kind < 0.6f) {
        int axis = int(u01(rng) * 3) % 3;
        dir[axis] = u01(rng) < 0.5f ? -1.0f : 1.0f;
    } else if (kind < 0.7f) {
        // One zero component: parallel to a coordinate plane.
        Vec3 d = randomUnit(rng);
        d[int(u01(rng) * 3) % 3] = 0;
        dir = normalize(d);
    } else {
        dir = randomUnit(rng);
    }
    return {origin, dir};
}

/// `rays` random rays (randomRay) through `bvh`: nearest hit and any-hit
/// must both be what brute force finds.
::testing::AssertionResult matchesBruteForce(const std::vector<Primitive>& prims, const Bvh& bvh,
                                             std::mt19937& rng, float spread, int rays) {
    for (int n = 0; n < rays; ++n) {
        Ray ray = randomRay(rng, prims, spread);
        ::testing::AssertionResult nearest = agrees(prims, bvh, ray, 0, kInfinity);
        if (!nearest) return nearest << ", ray " << n;
        if (bvh.occluded(ray, 0, kInfinity) != bruteAny(prims, ray, 0, kInfinity))
            return ::testing::AssertionFailure() << "any-hit differs, ray " << n;
    }
    return ::testing::AssertionSuccess();
}

TEST(Bvh, EmptyScene) {
    Bvh bvh;
    bvh.build({});
    HitRecord hit;
    Ray ray{{0, 0, 0}, {0, 0, 1}};
    EXPECT_FALSE(bvh.intersect(ray, 0, kInfinity, hit));
    EXPECT_FALSE(bvh.occluded(ray, 0, kInfinity));
    EXPECT_TRUE(bvh.nodes().empty());
    // Rebuilding over nothing after a real scene forgets the old one.
    std::vector<Primitive> one{
        makePrimitive(ShapeKind::Sphere, {1, 0, 0}, Transform::fromPose({0, 0, 5}, {}))};
    bvh.build(one);
    EXPECT_TRUE(bvh.intersect(ray, 0, kInfinity, hit));
    bvh.build({});
    EXPECT_FALSE(bvh.intersect(ray, 0, kInfinity, hit));
    EXPECT_FALSE(bvh.occluded(ray, 0, kInfinity));
}

TEST(Bvh, SinglePrimitive) {
    // Box 2x2x2 at (0,0,10): the ray along +z from the origin enters z=9 at t=9.
    std::vector<Primitive> prims{
        makePrimitive(ShapeKind::Box, {2, 2, 2}, Transform::fromPose({0, 0, 10}, {}))};
    Bvh bvh;
    bvh.build(prims);
    Ray ray{{0, 0, 0}, {0, 0, 1}};
    HitRecord hit;
    ASSERT_TRUE(bvh.intersect(ray, 0, kInfinity, hit));
    EXPECT_EQ(hit.primitive, 0u);
    EXPECT_NEAR(hit.t, 9.0f, 1e-5f);
    EXPECT_EQ(hit.face, Face::SlabZ);
    EXPECT_TRUE(bvh.occluded(ray, 0, kInfinity));
    // tMax before the box: nothing; tMin past the entry: the exit z=11.
    EXPECT_FALSE(bvh.intersect(ray, 0, 8.5f, hit));
    EXPECT_FALSE(bvh.occluded(ray, 0, 8.5f));
    ASSERT_TRUE(bvh.intersect(ray, 9.5f, kInfinity, hit));
    EXPECT_NEAR(hit.t, 11.0f, 1e-5f);
    // Off to the side: x=1.5 > 1.
    EXPECT_FALSE(bvh.intersect({{1.5f, 0, 0}, {0, 0, 1}}, 0, kInfinity, hit));
    EXPECT_FALSE(bvh.occluded({{1.5f, 0, 0}, {0, 0, 1}}, 0, kInfinity));
}

TEST(Bvh, NearestOfTwoInALine) {
    // Spheres r=1 at z=10 and z=20 on the ray's line: the nearer (index 1) at t=9,
    // whatever the order of the input.
    std::vector<Primitive> prims{
        makePrimitive(ShapeKind::Sphere, {1, 0, 0}, Transform::fromPose({0, 0, 20}, {})),
        makePrimitive(ShapeKind::Sphere, {1, 0, 0}, Transform::fromPose({0, 0, 10}, {}))};
    Bvh bvh;
    bvh.build(prims);
    HitRecord hit;
    ASSERT_TRUE(bvh.intersect({{0, 0, 0}, {0, 0, 1}}, 0, kInfinity, hit));
    EXPECT_EQ(hit.primitive, 1u);
    EXPECT_NEAR(hit.t, 9.0f, 1e-5f);
    // Looking back from z=30: the z=20 sphere at t = 30-21 = 9.
    ASSERT_TRUE(bvh.intersect({{0, 0, 30}, {0, 0, -1}}, 0, kInfinity, hit));
    EXPECT_EQ(hit.primitive, 0u);
    EXPECT_NEAR(hit.t, 9.0f, 1e-5f);
}

TEST(BvhProperty, MatchesBruteForceOnRandomScenes) {
    const std::uint32_t seed = test::testSeed(8675309u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    int hits = 0, rays = 0;
    Bvh bvh;  // reused across scenes, as the renderer does per frame
    for (int count : {2, 5, 17, 100, 600}) {
        const float spread = 100;
        std::vector<Primitive> prims = randomScene(rng, count, spread);
        bvh.build(prims);
        auto [depth, leafPrims] = inspectTree(bvh);
        EXPECT_EQ(leafPrims, std::uint64_t(count)) << "every primitive in exactly one leaf";
        EXPECT_GT(depth, 0);
        for (int n = 0; n < test::randomCases(3000); ++n, ++rays) {
            Ray ray = randomRay(rng, prims, spread);
            float tMin = u01(rng) < 0.5f ? 0.0f : 1e-3f;
            float tMax = u01(rng) < 0.5f ? kInfinity : 1 + 300 * u01(rng);
            ASSERT_TRUE(agrees(prims, bvh, ray, tMin, tMax)) << "scene of " << count << ", ray " << n;
            ASSERT_EQ(bvh.occluded(ray, tMin, tMax), bruteAny(prims, ray, tMin, tMax))
                << "scene of " << count << ", ray " << n << " origin " << ray.origin << " dir "
                << ray.direction << " tMax " << tMax;
            hits += bruteNearest(prims, ray, tMin, tMax).found;
        }
    }
    // The comparison is not vacuous: a good share of rays hit something.
    EXPECT_GT(hits, rays / 4);
}

TEST(BvhProperty, RefitAfterMotionMatchesBruteForce) {
    // Bvh::update refits the last tree (in parallel subtrees, on a pool) when
    // the primitives move a little, and rebuilds when refitting degrades it;
    // either way every query must still match brute force. 3000 primitives
    // make a tree deep enough to have parallel refit subtrees below the top.
    const std::uint32_t seed = test::testSeed(1234567u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), jitter(-3.0f, 3.0f), far(-400.0f, 400.0f);
    const float spread = 300;
    std::vector<Primitive> prims = randomScene(rng, 3000, spread);
    ThreadPool pool(3);
    Bvh bvh;
    EXPECT_TRUE(bvh.update(prims, &pool)) << "the first update builds";
    int refits = 0, rebuilds = 0;
    for (int frame = 0; frame < 6; ++frame) {
        // Frames 0-3 jiggle every primitive; frames 4-5 throw a third of them far away.
        for (Primitive& p : prims) {
            Vec3 move = frame < 4 ? Vec3{jitter(rng), jitter(rng), jitter(rng)}
                                  : (u01(rng) < 0.33f ? Vec3{far(rng), far(rng), far(rng)} : Vec3{});
            p.centre = p.centre + move;
        }
        bool rebuilt = bvh.update(prims, frame % 2 ? &pool : nullptr);
        (rebuilt ? rebuilds : refits) += 1;
        auto [depth, leafPrims] = inspectTree(bvh);  // also checks that parents contain children
        EXPECT_EQ(leafPrims, prims.size());
        EXPECT_GT(depth, 8);
        ASSERT_TRUE(matchesBruteForce(prims, bvh, rng, spread, test::randomCases(1500))) << "frame " << frame;
    }
    EXPECT_GE(refits, 4) << "small motion refits instead of rebuilding";
    std::cout << "[   INFO   ] refit test: " << refits << " refits, " << rebuilds << " rebuilds\n";
}

TEST(BvhProperty, DegradedSubtreesAreRebuiltInPlace) {
    // Clusters that keep their place while their members shuffle inside them:
    // refitting degrades the subtrees below the top of the tree, not the top,
    // so update() rebuilds those subtrees (a few per call) instead of the whole
    // tree. The rebuilt tree must still contain its children, hold every
    // primitive once, use no more live nodes than a binary tree can, and
    // answer every query as brute force does.
    const std::uint32_t seed = test::testSeed(8675309u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), inside(-30.0f, 30.0f), place(-500.0f, 500.0f);
    const int clusters = 100, members = 40;
    std::vector<Primitive> prims = randomScene(rng, clusters * members, 5.0f);
    std::vector<Vec3> centres(clusters);
    for (Vec3& c : centres) c = {place(rng), place(rng), place(rng)};
    auto shuffle = [&](int cluster) {
        for (int m = 0; m < members; ++m)
            prims[std::size_t(cluster * members + m)].centre =
                centres[std::size_t(cluster)] + Vec3{inside(rng), inside(rng), inside(rng)};
    };
    for (int c = 0; c < clusters; ++c) shuffle(c);
    ThreadPool pool(2);
    Bvh bvh;
    ASSERT_TRUE(bvh.update(prims, &pool));
    int subtreeRebuilds = 0, fullRebuilds = 0;
    for (int frame = 0; frame < 10; ++frame) {
        for (int k = 0; k < 4; ++k) shuffle(int(u01(rng) * clusters) % clusters);
        fullRebuilds += bvh.update(prims, frame % 2 ? &pool : nullptr);
        subtreeRebuilds += int(bvh.subtreesRebuilt());
        auto [depth, leafPrims] = inspectTree(bvh);
        EXPECT_EQ(leafPrims, prims.size());
        EXPECT_LE(bvh.liveNodeCount(), 2 * prims.size() - 1);
        ASSERT_TRUE(matchesBruteForce(prims, bvh, rng, 500, test::randomCases(1000))) << "frame " << frame;
    }
    EXPECT_GT(subtreeRebuilds, 0) << "shuffled clusters degrade their subtrees";
    std::cout << "[   INFO   ] subtree test: " << subtreeRebuilds << " subtree rebuilds, " << fullRebuilds
              << " full rebuilds\n";
}

TEST(BvhProperty, StagedRebuildSpreadsItsWorkOverFrames) {
    // Primitives flying straight across the scene wear out the top of the
    // tree, which no subtree rebuild mends. A tree this large is then rebuilt
    // in stages: at this pace no update() builds the whole tree in one call,
    // none splits more than about half a whole build's worth, the old tree is
    // refitted until the new one is complete and put in, and every query
    // matches brute force before, during and after.
    const std::uint32_t seed = test::testSeed(20261202u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> speed(-3.0f, 3.0f);
    const std::uint32_t n = Bvh::kStagedBuildMin + 1904;
    const float spread = 300;
    std::vector<Primitive> prims = randomScene(rng, int(n), spread);
    std::vector<Vec3> velocity(n);
    for (Vec3& v : velocity) v = {speed(rng), speed(rng), speed(rng)};
    ThreadPool pool(2);
    Bvh bvh;
    ASSERT_TRUE(bvh.update(prims, &pool));
    EXPECT_EQ(bvh.lastUpdate().action, Bvh::UpdateAction::Rebuilt) << "the first update builds";
    // Half of it, with room for later trees to need a little more splitting than the first.
    const std::uint64_t wholeBuild = bvh.lastUpdate().splitWork, bound = wholeBuild * 6 / 10;
    EXPECT_GT(wholeBuild, 8 * std::uint64_t(n)) << "splitting every level sorts every primitive";
    int staged = 0, swapped = 0;
    for (int frame = 0; frame < 40; ++frame) {
        for (std::uint32_t i = 0; i < n; ++i) prims[i].centre = prims[i].centre + velocity[i];
        const bool renewed = bvh.update(prims, frame % 2 ? &pool : nullptr);
        const Bvh::UpdateReport& report = bvh.lastUpdate();
        EXPECT_NE(report.action, Bvh::UpdateAction::Rebuilt) << "frame " << frame;
        EXPECT_LE(report.splitWork, bound) << "frame " << frame;
        EXPECT_EQ(renewed, report.action == Bvh::UpdateAction::Swapped) << "frame " << frame;
        staged += report.action == Bvh::UpdateAction::Staged;
        swapped += report.action == Bvh::UpdateAction::Swapped;
        auto [depth, leafPrims] = inspectTree(bvh);  // also checks that parents contain children
        EXPECT_EQ(leafPrims, n);
        EXPECT_LE(bvh.liveNodeCount(), 2 * std::size_t(n) - 1);
        ASSERT_TRUE(matchesBruteForce(prims, bvh, rng, spread, test::randomCases(250))) << "frame " << frame;
    }
    EXPECT_GE(swapped, 2) << "the flight wears the tree out again and again";
    EXPECT_GT(staged, swapped) << "each staged rebuild takes more than one frame";
    std::cout << "[   INFO   ] staged test: " << swapped << " staged trees put in, " << staged
              << " frames with a rebuild under way\n";
}

TEST(BvhProperty, ParallelBuildMakesTheSameTree) {
    // With a pool, subtrees are built on its threads into their own arrays and
    // appended: the splits must be those of the serial build (same leaves, same
    // SAH cost), only laid out differently, and every query must still agree.
    const std::uint32_t seed = test::testSeed(424242u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    const float spread = 600;
    std::vector<Primitive> prims = randomScene(rng, 10000, spread);
    Bvh serial, parallel;
    serial.build(prims);
    ThreadPool pool(4);
    parallel.build(prims, &pool);
    ASSERT_EQ(parallel.nodes().size(), serial.nodes().size());
    EXPECT_NEAR(parallel.sahCost(), serial.sahCost(), 1e-4 * serial.sahCost());
    auto [depthS, leafPrimsS] = inspectTree(serial);
    auto [depthP, leafPrimsP] = inspectTree(parallel);
    EXPECT_EQ(depthP, depthS);
    EXPECT_EQ(leafPrimsP, prims.size());
    // Same leaf order: the primitives end up in the same places.
    ASSERT_EQ(parallel.originalIndices().size(), serial.originalIndices().size());
    EXPECT_TRUE(std::equal(parallel.originalIndices().begin(), parallel.originalIndices().end(),
                           serial.originalIndices().begin()));
    for (int n = 0; n < test::randomCases(3000); ++n) {
        Ray ray = randomRay(rng, prims, spread);
        ASSERT_TRUE(agrees(prims, parallel, ray, 0, kInfinity)) << "ray " << n;
        ASSERT_EQ(parallel.occluded(ray, 0, kInfinity), bruteAny(prims, ray, 0, kInfinity)) << "ray " << n;
    }
    // And it refits like any other tree.
    for (Primitive& p : prims) p.centre = p.centre + Vec3{1, -2, 0.5f};
    EXPECT_FALSE(parallel.update(prims, &pool));
    for (int n = 0; n < test::randomCases(1000); ++n)
        ASSERT_TRUE(agrees(prims, parallel, randomRay(rng, prims, spread), 0, kInfinity))
            << "after refit, ray " << n;
}

TEST(BvhProperty, EntryNodesOfATileLoseNoHit) {
    // A tile's packets start from Bvh::entryNodes() of its frustum instead of
    // the root: for random cameras and tiles, every ray through the tile must
    // find with the packet traversal from those nodes exactly what the
    // single-ray traversal from the root finds.
    const std::uint32_t seed = test::testSeed(31337u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), angle(-180.0f, 180.0f);
    const float spread = 300;
    std::vector<Primitive> prims = randomScene(rng, 3000, spread);
    Bvh bvh;
    bvh.build(prims);
    int hits = 0, rays = 0, trimmed = 0;
    for (int view = 0; view < test::randomCases(40); ++view) {
        Camera camera;
        camera.width = 160;
        camera.height = 120;
        // From outside the scene looking in, and from inside it.
        float r = view % 2 ? 2.5f * spread : 0.3f * spread;
        Vec3 dir = randomUnit(rng);
        camera.eye = dir * r;
        camera.worldFromCamera = rotationFromEulerDegrees(angle(rng) * 0.25f, angle(rng), angle(rng) * 0.1f);
        for (int tile = 0; tile < 12; ++tile) {
            int size = 4 << (tile % 3);  // 4, 8, 16 pixels
            int x0 = int(u01(rng) * float(camera.width - size)),
                y0 = int(u01(rng) * float(camera.height - size));
            std::uint32_t store[8];
            std::size_t count =
                bvh.entryNodes(camera.pixelFrustum(x0, y0, x0 + size, y0 + size), camera.eye, store);
            trimmed += count != 1 || store[0] != 0;
            std::span<const std::uint32_t> entry(store, count);
            for (int packet = 0; packet < 4; ++packet) {
                alignas(64) float dx[simd::kWidth], dy[simd::kWidth], dz[simd::kWidth];
                std::vector<Ray> lanes;
                for (int i = 0; i < simd::kWidth; ++i) {
                    Ray ray = camera.rayThrough(float(x0) + u01(rng) * float(size),
                                                float(y0) + u01(rng) * float(size));
                    dx[i] = ray.direction.x, dy[i] = ray.direction.y, dz[i] = ray.direction.z;
                    lanes.push_back(ray);
                }
                EyeRays packetRays(camera.eye, Vec3P(simd::load(dx), simd::load(dy), simd::load(dz)));
                PacketHit hit;
                intersectPacket(bvh, packetRays, simd::allLanes(), Float(0.0f), hit, entry);
                alignas(64) float t[simd::kWidth];
                alignas(64) std::int32_t prim[simd::kWidth];
                simd::store(t, hit.t);
                simd::store(prim, hit.primitive);
                for (int i = 0; i < simd::kWidth; ++i, ++rays) {
                    HitRecord expected;
                    bool found = bvh.intersect(lanes[std::size_t(i)], 0, kInfinity, expected);
                    ASSERT_EQ(t[i] < kInfinity, found)
                        << "view " << view << " tile " << tile << " lane " << i;
                    if (!found) continue;
                    ++hits;
                    EXPECT_EQ(t[i], expected.t) << "view " << view << " tile " << tile << " lane " << i;
                    EXPECT_EQ(bvh.originalIndices()[std::size_t(prim[i])], expected.primitive);
                }
            }
        }
    }
    // Not vacuous: many rays hit, and many tiles start below the root.
    EXPECT_GT(hits, rays / 5);
    EXPECT_GT(trimmed, test::randomCases(40));
    std::cout << "[   INFO   ] entry nodes: " << hits << " of " << rays << " rays hit; " << trimmed
              << " of 480 tiles start below the root\n";
}

/// Lanes of a shadow packet (one direction, an origin per lane) that the
/// packet traversal finds blocked, checked lane by lane against brute force.
void expectShadowPacketMatchesBruteForce(const Bvh& bvh, const std::vector<Primitive>& prims,
                                         const std::vector<Vec3>& origins, Vec3 direction, const char* what) {
    alignas(64) float ox[simd::kWidth], oy[simd::kWidth], oz[simd::kWidth];
    for (int i = 0; i < simd::kWidth; ++i) {
        Vec3 o = origins[std::size_t(i) % origins.size()];
        ox[i] = o.x, oy[i] = o.y, oz[i] = o.z;
    }
    ParallelRays packet(Vec3P(simd::load(ox), simd::load(oy), simd::load(oz)), direction);
    std::uint32_t blocked =
        simd::bits(occludedPacket(bvh, packet, simd::allLanes(), Float(0.0f), Float(kInfinity), Int(-1)));
    for (int i = 0; i < simd::kWidth; ++i) {
        Ray ray{origins[std::size_t(i) % origins.size()], direction};
        ASSERT_EQ(((blocked >> i) & 1u) != 0, bruteAny(prims, ray, 0, kInfinity))
            << what << ": lane " << i << " origin " << ray.origin.x << ' ' << ray.origin.y << ' '
            << ray.origin.z << " direction " << direction.x << ' ' << direction.y << ' ' << direction.z;
    }
}

TEST(BvhProperty, ShadowPacketsMatchBruteForce) {
    // Shadow packets share one direction, so the traversal works out the slab
    // order once: for random scenes, origins and directions (some along the
    // axes, with zero components), each lane must agree with brute force.
    const std::uint32_t seed = test::testSeed(4242u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> coordinate(-300.0f, 300.0f);
    std::vector<Primitive> prims = randomScene(rng, 2000, 300);
    Bvh bvh;
    bvh.build(prims);
    const Vec3 axial[] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0.6f, 0, -0.8f}};
    int blockedLanes = 0;
    for (int packet = 0; packet < test::randomCases(400); ++packet) {
        Vec3 direction = packet % 4 == 0 ? axial[(packet / 4) % 4] : randomUnit(rng);
        std::vector<Vec3> origins;
        for (int i = 0; i < simd::kWidth; ++i)
            origins.push_back({coordinate(rng), coordinate(rng), coordinate(rng)});
        expectShadowPacketMatchesBruteForce(bvh, prims, origins, direction, "random");
        if (HasFatalFailure()) return;
        for (const Vec3& o : origins) blockedLanes += bruteAny(prims, {o, direction}, 0, kInfinity);
    }
    EXPECT_GT(blockedLanes,
              test::randomCases(400) * simd::kWidth / 10);  // not vacuous: many lanes are blocked
}

TEST(BvhProperty, GrazingShadowPacketsFarFromTheOrigin) {
    // The any-hit walk's box tests must pass every ray that meets a primitive
    // inside the box, whatever their rounding (the padding of primitiveBounds()
    // covers it). Far from the origin, where float spacing is coarse, rays
    // aimed at the corners and edges of unrotated boxes and at the rims of
    // spheres (so that they graze them) must be blocked exactly when brute
    // force says so. Boxes shrunk by 10^-6 of their coordinates fail this.
    const std::uint32_t seed = test::testSeed(31337u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), coordinate(-4000.0f, 4000.0f);
    const Vec3 far{30000.0f, -20000.0f, 25000.0f};  // sparse: the grazed primitive decides most rays
    std::vector<Primitive> prims;
    for (int i = 0; i < 1500; ++i) {
        const Vec3 at = far + Vec3{coordinate(rng), coordinate(rng), coordinate(rng)};
        const float size = 2.0f + 30.0f * u01(rng);
        prims.push_back(i % 2 ? makePrimitive(ShapeKind::Box, {size, 0.5f * size, 1.5f * size},
                                              Transform::fromPose(at, {}))
                              : makePrimitive(ShapeKind::Sphere, {size, 0, 0}, Transform::fromPose(at, {})));
    }
    Bvh bvh;
    bvh.build(prims);
    int blockedLanes = 0;
    for (int packet = 0; packet < test::randomCases(300); ++packet) {
        const Vec3 direction = randomUnit(rng);
        std::vector<Vec3> origins;
        for (int i = 0; i < simd::kWidth; ++i) {
            const Primitive& p = prims[std::size_t(u01(rng) * prims.size()) % prims.size()];
            Vec3 target;
            if (p.kind == ShapeKind::Box) {
                // A corner, or a point on an edge.
                Vec3 f{u01(rng) < 0.5f ? -1.0f : 1.0f, u01(rng) < 0.5f ? -1.0f : 1.0f,
                       u01(rng) < 0.5f ? -1.0f : 1.0f};
                if (i % 2) f[i % 3] = 2 * u01(rng) - 1;
                target = p.centre + Vec3{f.x * p.half.x, f.y * p.half.y, f.z * p.half.z};
            } else {
                // A point of the sphere's rim seen along the rays.
                Vec3 side = cross(direction, randomUnit(rng));
                target = p.centre + normalize(side) * p.half.x;
            }
            origins.push_back(target - direction * (50.0f + 300.0f * u01(rng)));
        }
        expectShadowPacketMatchesBruteForce(bvh, prims, origins, direction, "grazing");
        if (HasFatalFailure()) return;
        for (const Vec3& o : origins) blockedLanes += bruteAny(prims, {o, direction}, 0, kInfinity);
    }
    // Not vacuous: many grazing rays are blocked, and many pass.
    EXPECT_GT(blockedLanes, test::randomCases(300) * simd::kWidth / 5);
    EXPECT_LT(blockedLanes, test::randomCases(300) * simd::kWidth * 4 / 5);
    std::cout << "[   INFO   ] grazing shadow rays: " << blockedLanes << " of "
              << test::randomCases(300) * simd::kWidth << " blocked\n";
}

TEST(BvhProperty, BeamEntryNodesLoseNoOccluder) {
    // A tile's shadow rays toward a light start from Bvh::beamEntryNodes() of
    // a box around their origins: for random boxes and directions (some along
    // the axes), rays from anywhere in the box must be blocked exactly when
    // brute force says so.
    const std::uint32_t seed = test::testSeed(8080u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f), coordinate(-300.0f, 300.0f);
    std::vector<Primitive> prims = randomScene(rng, 3000, 300);
    Bvh bvh;
    bvh.build(prims);
    const Vec3 axial[] = {{0, 1, 0}, {-1, 0, 0}, {0, 0, -1}, {0.8f, 0, 0.6f}};
    int blockedLanes = 0, trimmed = 0;
    for (int beam = 0; beam < test::randomCases(200); ++beam) {
        Vec3 direction = beam % 4 == 0 ? axial[(beam / 4) % 4] : randomUnit(rng);
        Vec3 corner{coordinate(rng), coordinate(rng), coordinate(rng)};
        Vec3 size = Vec3{u01(rng), u01(rng), u01(rng)} * (beam % 2 ? 5.0f : 60.0f);
        Bounds origins{corner, corner + size};
        std::uint32_t store[8];
        std::size_t count = bvh.beamEntryNodes(origins, direction, store);
        trimmed += count != 1 || store[0] != 0;
        std::span<const std::uint32_t> entry(store, count);
        alignas(64) float ox[simd::kWidth], oy[simd::kWidth], oz[simd::kWidth];
        for (int i = 0; i < simd::kWidth; ++i) {
            // Corners of the box, then points inside it.
            Vec3 f = i < 8 ? Vec3{float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)}
                           : Vec3{u01(rng), u01(rng), u01(rng)};
            ox[i] = corner.x + f.x * size.x, oy[i] = corner.y + f.y * size.y, oz[i] = corner.z + f.z * size.z;
        }
        ParallelRays rays(Vec3P(simd::load(ox), simd::load(oy), simd::load(oz)), direction);
        std::uint32_t blocked = simd::bits(
            occludedPacket(bvh, rays, simd::allLanes(), Float(0.0f), Float(kInfinity), Int(-1), entry));
        for (int i = 0; i < simd::kWidth; ++i) {
            bool expected = bruteAny(prims, {{ox[i], oy[i], oz[i]}, direction}, 0, kInfinity);
            ASSERT_EQ(((blocked >> i) & 1u) != 0, expected) << "beam " << beam << " lane " << i;
            blockedLanes += expected;
        }
    }
    // Not vacuous: many lanes are blocked, and most beams start below the root.
    EXPECT_GT(blockedLanes, test::randomCases(200) * simd::kWidth / 10);
    EXPECT_GT(trimmed, test::randomCases(100));
    std::cout << "[   INFO   ] beam entry nodes: " << blockedLanes << " of "
              << test::randomCases(200) * simd::kWidth << " rays blocked; " << trimmed
              << " of 200 beams start below the root\n";
}

TEST(BvhProperty, OriginsInsidePrimitives) {
    // Rays starting inside (overlapping) primitives: the nearest crossing may be an exit.
    const std::uint32_t seed = test::testSeed(55555u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::vector<Primitive> prims = randomScene(rng, 300, 30);  // dense: much overlap
    Bvh bvh;
    bvh.build(prims);
    for (int n = 0; n < 3000; ++n) {
        const Primitive& p = prims[std::size_t(u01(rng) * prims.size()) % prims.size()];
        Ray ray{p.centre, randomUnit(rng)};
        ASSERT_TRUE(agrees(prims, bvh, ray, 0, kInfinity)) << "ray " << n;
        ASSERT_TRUE(bvh.occluded(ray, 0, kInfinity)) << "ray " << n << " starts inside a primitive";
    }
}

TEST(Bvh, CoincidentPrimitives) {
    // 1000 identical spheres r=1 at (3,4,5): no split separates equal centroids.
    std::vector<Primitive> prims(
        1000, makePrimitive(ShapeKind::Sphere, {1, 0, 0}, Transform::fromPose({3, 4, 5}, {})));
    Bvh bvh;
    bvh.build(prims);
    auto [depth, leafPrims] = inspectTree(bvh);
    EXPECT_EQ(leafPrims, 1000u);
    // Halving 1000 down to small leaves takes ~10 levels; anything near the
    // traversal stack's size would mean an unbalanced (linear) tree.
    std::cout << "[   INFO   ] coincident: " << bvh.nodes().size() << " nodes, depth " << depth << '\n';
    EXPECT_LE(depth, 32);
    HitRecord hit;
    // From (3,4,-10) along +z: the sphere's near point z = 5-1 = 4, t = 14.
    ASSERT_TRUE(bvh.intersect({{3, 4, -10}, {0, 0, 1}}, 0, kInfinity, hit));
    EXPECT_NEAR(hit.t, 14.0f, 1e-5f);
    EXPECT_LT(hit.primitive, 1000u);
    EXPECT_TRUE(bvh.occluded({{3, 4, -10}, {0, 0, 1}}, 0, kInfinity));
    EXPECT_FALSE(bvh.occluded({{3, 4, -10}, {0, 0, 1}}, 0, 13.5f));
    EXPECT_FALSE(bvh.intersect({{3, 5.5f, -10}, {0, 0, 1}}, 0, kInfinity, hit));
}

TEST(Bvh, HostileExponentialLine) {
    // 100000 spheres r=1e-4 on the x axis at x_i = exp(0.0008 i): from 1 to e^80 ~ 5.5e34.
    // Neighbours are 0.0008 x_i apart (>= 8e-4 > 2r), so the spheres never overlap, while
    // the centroid spread defeats uniform binning and overflows surface areas.
    const int n = 100000;
    const float r = 1e-4f;
    std::vector<Primitive> prims;
    prims.reserve(n);
    for (int i = 0; i < n; ++i)
        prims.push_back(makePrimitive(ShapeKind::Sphere, {r, 0, 0},
                                      Transform::fromPose({float(std::exp(0.0008 * i)), 0, 0}, {})));
    Bvh bvh;
    bvh.build(prims);
    auto [depth, leafPrims] = inspectTree(bvh);
    EXPECT_EQ(leafPrims, std::uint64_t(n));
    // The traversal uses a fixed stack; the depth must stay far from unbounded.
    std::cout << "[   INFO   ] exponential line: " << bvh.nodes().size() << " nodes, depth " << depth << '\n';
    EXPECT_LE(depth, 100);

    const std::uint32_t seed = test::testSeed(4242u);
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> pick(0, n - 1);
    HitRecord hit;
    for (int k = 0; k < 2000; ++k) {
        // Straight down onto sphere i from 10 above its centre: t = 10 - r, index i.
        int i = pick(rng);
        Ray down{{prims[i].centre.x, 10, 0}, {0, -1, 0}};
        ASSERT_TRUE(bvh.intersect(down, 0, kInfinity, hit)) << "sphere " << i;
        EXPECT_EQ(hit.primitive, std::uint32_t(i));
        EXPECT_NEAR(hit.t, 10 - r, 1e-5f);
        ASSERT_TRUE(bvh.occluded(down, 0, kInfinity)) << "sphere " << i;
        // Along +x from midway between spheres i and i+1: sphere i+1 at x_{i+1} - r.
        if (i + 1 < n) {
            float xa = prims[i].centre.x, xb = prims[i + 1].centre.x;
            float mid = xa + (xb - xa) / 2;
            Ray along{{mid, 0, 0}, {1, 0, 0}};
            ASSERT_TRUE(bvh.intersect(along, 0, kInfinity, hit)) << "after sphere " << i;
            EXPECT_EQ(hit.primitive, std::uint32_t(i + 1));
            EXPECT_NEAR(hit.t, (xb - mid) - r, 1e-4f * (xb - mid));
        }
        if (HasFailure()) return;
    }
    // From the origin along +x: sphere 0 (x=1) at t = 1 - r.
    ASSERT_TRUE(bvh.intersect({{0, 0, 0}, {1, 0, 0}}, 0, kInfinity, hit));
    EXPECT_EQ(hit.primitive, 0u);
    EXPECT_NEAR(hit.t, 1 - r, 1e-6f);
    // Back along -x from past the last sphere: the last one.
    float last = prims[n - 1].centre.x;
    ASSERT_TRUE(bvh.intersect({{last * 2, 0, 0}, {-1, 0, 0}}, 0, kInfinity, hit));
    EXPECT_EQ(hit.primitive, std::uint32_t(n - 1));
    // Brute force on a subset of random rays (mostly misses, a few aimed).
    for (int k = 0; k < 100; ++k) {
        int i = pick(rng);
        Vec3 c = prims[i].centre;
        Vec3 from = c + randomUnit(rng) * (0.5f + std::fabs(c.x) * 1e-3f);
        Ray ray{from, normalize(c - from)};
        ASSERT_TRUE(agrees(prims, bvh, ray, 0, kInfinity)) << "aimed ray " << k;
        ASSERT_EQ(bvh.occluded(ray, 0, kInfinity), bruteAny(prims, ray, 0, kInfinity)) << "aimed ray " << k;
    }
}

}  // namespace
}  // namespace f2
