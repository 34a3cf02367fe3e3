// prepareFrame (render/frame_preparation.h), which evaluates straight into the
// BVH's leaves when the last tree is refitted, gives what evaluateFrame then
// Bvh::update give, bit for bit: the frame's primitives, the tree, the leaf
// order, the rebuild decisions; over playback forwards, backwards, by jumps
// that force rebuilds, the same time again, on a pool and serially, and for a
// frame as large as those that take that path by default.
#include "core/render/frame_preparation.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "core/anim/animation_program.h"
#include "core/anim/frame_builder.h"
#include "io/bench_scenes.h"
#include "test_scenes.h"

namespace f2 {
namespace {

bool sameBits(Vec3 a, Vec3 b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool samePrimitive(const Primitive& a, const Primitive& b) {
    return sameBits(a.centre, b.centre) && sameBits(a.axes[0], b.axes[0]) && sameBits(a.axes[1], b.axes[1]) &&
           sameBits(a.axes[2], b.axes[2]) && sameBits(a.half, b.half) && a.kind == b.kind &&
           a.axisAligned == b.axisAligned;
}

/// Everything the tracer reads of `frame` is as in `reference`.
void expectSamePrepared(const PreparedFrame& reference, const PreparedFrame& frame, const std::string& what) {
    ASSERT_EQ(frame.primitives.size(), reference.primitives.size()) << what;
    for (std::size_t i = 0; i < frame.primitives.size(); ++i)
        ASSERT_TRUE(samePrimitive(reference.primitives[i], frame.primitives[i]))
            << what << ": primitive " << i;
    const auto ordered = frame.bvh.orderedPrimitives(), orderedWanted = reference.bvh.orderedPrimitives();
    ASSERT_EQ(ordered.size(), orderedWanted.size()) << what;
    for (std::size_t i = 0; i < ordered.size(); ++i) {
        ASSERT_TRUE(samePrimitive(orderedWanted[i], ordered[i])) << what << ": leaf slot " << i;
        ASSERT_EQ(frame.bvh.originalIndices()[i], reference.bvh.originalIndices()[i]) << what;
    }
    const auto nodes = frame.bvh.nodes(), nodesWanted = reference.bvh.nodes();
    ASSERT_EQ(nodes.size(), nodesWanted.size()) << what;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Bvh::Node &a = nodesWanted[i], &b = nodes[i];
        ASSERT_TRUE(sameBits(a.bounds.lo, b.bounds.lo) && sameBits(a.bounds.hi, b.bounds.hi) &&
                    a.first == b.first && a.count == b.count && a.axis == b.axis)
            << what << ": node " << i;
    }
    EXPECT_EQ(frame.bvh.subtreesRebuilt(), reference.bvh.subtreesRebuilt()) << what;
}

/// Of a playback: frames that took the path that evaluates into the leaves,
/// and refits followed by a rebuild (whole tree or subtrees).
struct PathsTaken {
    int intoLeaves = 0, rebuiltAfterRefit = 0;
};

/// Prepares `scene` at each of `times` in turn, serially and on a pool, and
/// compares with evaluateFrame + Bvh::update fed the same times.
PathsTaken expectSameAsEvaluateThenUpdate(const SceneDesc& scene, const std::vector<double>& times,
                                          const std::string& name) {
    ThreadPool pool(2);
    // A tree built on a pool lays its nodes out in another order than a serial
    // build: each is compared with its own kind.
    PreparedFrame serialReference, pooledReference, serial, pooled;
    PathsTaken paths;
    for (double t : times) {
        const std::string what = name + " at t = " + std::to_string(t);
        // The path taken: a refilled frame whose tree is refitted.
        const auto program = animationProgramOf(scene);
        const bool intoLeaves =
            pooled.filledBy == program && pooled.bvh.refits(program->firstPrimitive.back());
        paths.intoLeaves += intoLeaves;

        evaluateFrame(scene, t, serialReference);
        serialReference.bvh.update(serialReference.primitives);
        // Small frames too take the path under test (kIntoLeavesFrom is for speed).
        prepareFrame(scene, t, serial, nullptr, 0);
        expectSamePrepared(serialReference, serial, what);
        evaluateFrame(scene, t, pooledReference, &pool);
        const bool rebuilt = pooledReference.bvh.update(pooledReference.primitives, &pool);
        paths.rebuiltAfterRefit += intoLeaves && (rebuilt || pooledReference.bvh.subtreesRebuilt() > 0);
        prepareFrame(scene, t, pooled, &pool, 0);
        expectSamePrepared(pooledReference, pooled, what + " (pool)");
        if (::testing::Test::HasFatalFailure()) break;
    }
    return paths;
}

/// Forwards by small steps, the same time again, backwards, and jumps across
/// the animation (which let the refitted tree degrade until it is rebuilt).
std::vector<double> playbackTimes(int last) {
    std::vector<double> times;
    for (int k = 0; k <= 12; ++k) times.push_back(0.5 * k);
    times.push_back(6.0);
    for (int k = 12; k >= 0; --k) times.push_back(0.75 * k);
    for (int k = 0; k < 10; ++k) times.push_back(double((k * 17) % (last + 1)) + 0.25);
    return times;
}

// Still objects (kept in place in both orders), attached ones, every model.
constexpr const char* kMixed =
    "/robot r 10 0 5 0 30 0\n/robot q 400 0 0 0 0 0\n/human h -100 0 40 0 -90 0\n"
    "/sphere s 5 0 0 0\n/box floor 2000 10 2000 0 -100 0\n/cylinder c 3 8 1 2 3 90 180 270\n"
    "/attach s r.rhand\n/attach c s\n"
    "/key 0 r\n/key 7 r 40 0 5 0 90 0\n/key 13 r 40 10 -5 10 90 -20\n/key 20 r 0 0 0 0 0 0\n"
    "/key 0 r.head 0 0 0 0 -40 0\n/key 9 r.head 0 1 0 10 40 0\n"
    "/key 0 h.body\n/key 10 h.body 0 0 0 20 0 0\n/key 20 h 300 0 0 0 0 0\n"
    "/key 0 s 0 -100 0 0 0 0\n/key 8 s 0 -80 0 0 90 0\n";

TEST(FramePreparation, MixedSceneMatchesEvaluateThenUpdateBitForBit) {
    const SceneDesc scene = test::sceneFromText(kMixed);
    EXPECT_GT(expectSameAsEvaluateThenUpdate(scene, playbackTimes(20), "mixed").intoLeaves, 30);
}

TEST(FramePreparation, RobotsMatchEvaluateThenUpdateBitForBit) {
    const BenchSceneSpec spec{BenchShape::Robots, 500};
    const SceneDesc scene = test::sceneFromText(benchSceneText(spec));
    const PathsTaken paths = expectSameAsEvaluateThenUpdate(scene, playbackTimes(48), benchSceneName(spec));
    EXPECT_GT(paths.intoLeaves, 30);
    EXPECT_GT(paths.rebuiltAfterRefit, 0);
}

TEST(FramePreparation, AFrameLargerThanTheCachesMatchesBitForBit) {
    // As many primitives as a frame that takes that path by default.
    const BenchSceneSpec spec{BenchShape::Robots, 11000};
    const SceneDesc scene = test::sceneFromText(benchSceneText(spec));
    ASSERT_GE(animationProgramOf(scene)->firstPrimitive.back(), kIntoLeavesFrom);
    EXPECT_EQ(expectSameAsEvaluateThenUpdate(scene, {3.0, 3.0, 7.5, 30.25}, benchSceneName(spec)).intoLeaves,
              3);
}

}  // namespace
}  // namespace f2
