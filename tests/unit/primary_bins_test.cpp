// Primary rays from screen-space bins (PrimaryBins) find exactly the hits of
// the walk from the root: lane by lane for random cameras, and image by image
// through the renderer.
#include "core/render/primary_bins.h"

#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <limits>
#include <random>
#include <string>

#include "core/anim/frame_builder.h"
#include "core/geometry/bvh_packet.h"
#include "core/render/renderer.h"
#include "core/render/shading.h"
#include "io/bench_scenes.h"
#include "test_scenes.h"

namespace f2 {
namespace {

constexpr int kBlockWidth = simd::kWidth >= 4 ? 4 : 1;
constexpr int kBlockHeight = simd::kWidth / kBlockWidth;

/// 100 robots on their floor, two spheres in the same place (every hit on them
/// a tie, which the lower frame index wins) and a long thin box across the crowd.
SceneDesc crowd() {
    BenchSceneSpec spec;
    spec.shape = BenchShape::Robots;
    spec.count = 100;
    return test::sceneFromText(benchSceneText(spec, 64, 48) +
                               "/sphere twin1 40 100 40 -200\n/sphere twin2 40 100 40 -200\n"
                               "/box rail 1500 6 6 0 20 100 0 30 0\n");
}

/// A camera at `eye` looking along (pitch, yaw, roll) degrees.
Camera lookingFrom(Vec3 eye, double pitch, double yaw, double roll, float distance, int width, int height) {
    Camera camera;
    camera.width = width;
    camera.height = height;
    camera.distance = distance;
    camera.eye = eye;
    camera.worldFromCamera = rotationFromEulerDegrees(pitch, yaw, roll);
    return camera;
}

struct Comparison {
    int cameras = 0, binned = 0;
    long lanes = 0, hits = 0, mismatches = 0;
};

/// For every block of `camera`'s image, rays through random points of its
/// pixels: the hits from the bins (as findSurfaces looks them up) against
/// those of the walk from the root, lane by lane.
void compareHits(const PreparedFrame& frame, const Camera& camera, float marginPixels, std::mt19937& rng,
                 Comparison& out) {
    PrimaryBins bins;
    bins.build(frame.bvh, camera, nullptr, 0, marginPixels);
    ++out.cameras;
    if (!bins.active()) return;
    ++out.binned;
    std::uniform_real_distribution<float> inPixel(0.0f, 0.999f);
    const Float tMin(primaryRayStart(camera.eye));
    for (int by = 0; by < camera.height; by += kBlockHeight)
        for (int bx = 0; bx < camera.width; bx += kBlockWidth) {
            alignas(64) float dx[simd::kWidth], dy[simd::kWidth], dz[simd::kWidth], inside[simd::kWidth];
            for (int i = 0; i < simd::kWidth; ++i) {
                const int x = bx + i % kBlockWidth, y = by + i / kBlockWidth;
                const Vec3 d = camera.rayThrough(float(x) + inPixel(rng), float(y) + inPixel(rng)).direction;
                dx[i] = d.x;
                dy[i] = d.y;
                dz[i] = d.z;
                inside[i] = x < camera.width && y < camera.height ? 1.0f : 0.0f;
            }
            const EyeRays rays(camera.eye, Vec3P(simd::load(dx), simd::load(dy), simd::load(dz)));
            const Mask active = simd::load(inside) > Float(0.0f);
            PacketHit fromRoot, fromBins;
            intersectPacket(frame.bvh, rays, active, tMin, fromRoot);
            const std::span<const std::uint32_t> cell = bins.cell(bx, by);
            if (cell.empty())
                intersectPacket(frame.bvh, rays, active, tMin, fromBins, bins.everywhere());
            else
                intersectPacket(frame.bvh, rays, active, tMin, fromBins, bins.everywhere(), cell);
            alignas(64) float t[2][simd::kWidth];
            alignas(64) std::int32_t primitive[2][simd::kWidth], face[2][simd::kWidth];
            simd::store(t[0], fromRoot.t);
            simd::store(t[1], fromBins.t);
            simd::store(primitive[0], fromRoot.primitive);
            simd::store(primitive[1], fromBins.primitive);
            simd::store(face[0], fromRoot.face);
            simd::store(face[1], fromBins.face);
            for (int i = 0; i < simd::kWidth; ++i) {
                if (inside[i] == 0) continue;
                ++out.lanes;
                out.hits += t[0][i] < kInfinity;
                out.mismatches += std::memcmp(&t[0][i], &t[1][i], sizeof(float)) != 0 ||
                                  primitive[0][i] != primitive[1][i] || face[0][i] != face[1][i];
            }
        }
}

/// Random cameras around and inside the crowd, some looking straight up or
/// down, some rolled, with boxes across their eye plane.
Comparison compareRandomCameras(float marginPixels) {
    const SceneDesc scene = crowd();
    PreparedFrame frame;
    evaluateFrame(scene, 7, frame);
    frame.bvh.build(frame.primitives);
    const Bounds box = frame.bvh.nodes()[0].bounds;
    std::mt19937 rng(test::testSeed(18));
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    Comparison result;
    for (int trial = 0; trial < 60; ++trial) {
        Vec3 eye;
        if (trial % 3 == 0) {  // among the robots, at their height
            eye = {box.lo.x + u01(rng) * (box.hi.x - box.lo.x), -105.0f + 60.0f * u01(rng),
                   box.lo.z + u01(rng) * (box.hi.z - box.lo.z)};
        } else {  // anywhere around
            eye = {-2500.0f + 5000.0f * u01(rng), -300.0f + 1800.0f * u01(rng),
                   -2500.0f + 5000.0f * u01(rng)};
        }
        double pitch = -90.0 + 180.0 * u01(rng);
        if (trial % 7 == 1) pitch = 90;   // straight down
        if (trial % 7 == 2) pitch = -90;  // straight up
        const double yaw = 360.0 * u01(rng), roll = trial % 4 == 3 ? 90.0 * u01(rng) : 0.0;
        const int width = trial % 2 ? 61 : 64, height = trial % 2 ? 47 : 48;
        compareHits(frame, lookingFrom(eye, pitch, yaw, roll, 0.3f + 1.2f * u01(rng), width, height),
                    marginPixels, rng, result);
    }
    // The bench scene's own camera and one just above the crowd, looking along it.
    const BenchCamera bench = benchCamera(100);
    compareHits(frame,
                lookingFrom(Vec3{float(bench.eyeX), float(bench.eyeY), float(bench.eyeZ)}, bench.pitch, 0, 0,
                            0.5f, 64, 48),
                marginPixels, rng, result);
    compareHits(frame, lookingFrom(Vec3{0, -40, box.lo.z - 10}, 5, 0, 0, 0.5f, 64, 48), marginPixels, rng,
                result);
    return result;
}

TEST(PrimaryBins, PacketHitsAreThoseOfTheWalkFromTheRoot) {
    const Comparison c = compareRandomCameras(PrimaryBins::kMarginPixels);
    std::cout << "[   INFO   ] " << c.binned << " of " << c.cameras << " cameras binned, " << c.lanes
              << " rays, " << c.hits << " hits\n";
    EXPECT_EQ(c.mismatches, 0);
    // Not vacuous: most cameras were binned, and many rays hit something.
    EXPECT_GT(c.binned, c.cameras * 2 / 3);
    EXPECT_GT(c.hits, c.lanes / 5);
}

TEST(PrimaryBins, AMarginTooSmallLosesHits) {
    // The same cameras with every projected box 1.5 pixels too narrow on each side.
    const Comparison c = compareRandomCameras(-1.5f);
    // (Measured: no lane differs down to -0.3 pixels, 4 at -0.6, 23 at -1, 140 at -1.5:
    // the boxes' own padding and the camera-space box around them leave some slack.)
    EXPECT_GT(c.mismatches, 20);
}

TEST(PrimaryBins, FallBackToTheTreeWhereBinningCannotPay) {
    const SceneDesc scene = crowd();
    PreparedFrame frame;
    evaluateFrame(scene, 0, frame);
    frame.bvh.build(frame.primitives);
    const Camera camera = lookingFrom(Vec3{0, 400, -1500}, 20, 0, 0, 0.5f, 64, 48);
    PrimaryBins bins;
    bins.build(frame.bvh, camera, nullptr, 0);
    EXPECT_TRUE(bins.active());
    EXPECT_GT(bins.entryCount(), 0u);
    bins.build(frame.bvh, camera, nullptr, frame.primitives.size() + 1);  // too few primitives
    EXPECT_FALSE(bins.active());
    Camera flat = camera;
    flat.distance = 0;  // no pinhole image
    bins.build(frame.bvh, flat, nullptr, 0);
    EXPECT_FALSE(bins.active());
}

/// The renderer's images with the bins forced on and off: the same bytes.
void expectSameImages(const SceneDesc& scene, double t, const Camera& camera, int threads, int aa,
                      const std::string& what) {
    Renderer binned(threads), walked(threads);
    binned.setPrimaryBinsFrom(0);
    walked.setPrimaryBinsFrom(std::numeric_limits<std::size_t>::max());
    Image a, b;
    binned.render(scene, t, camera, a, {aa});
    walked.render(scene, t, camera, b, {aa});
    ASSERT_EQ(a.pixels.size(), b.pixels.size()) << what;
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb8)), 0) << what;
}

TEST(PrimaryBins, ImagesAreThoseOfTheTreeWalk) {
    SceneDesc demo = test::sceneFromRepo("demo.f2");
    demo.camera.width = 203;  // not a multiple of the block or tile size
    demo.camera.height = 149;
    for (double t : {0.0, 118.0, 240.0})
        expectSameImages(demo, t, cameraAt(demo, t), 2, 1, "demo at " + std::to_string(t));
    expectSameImages(demo, 47.5, cameraAt(demo, 47.5), 3, 3, "demo, --aa 3, 3 threads");

    const SceneDesc robots = crowd();
    const BenchCamera bench = benchCamera(100);
    const Camera overview = lookingFrom(Vec3{float(bench.eyeX), float(bench.eyeY), float(bench.eyeZ)},
                                        bench.pitch, 0, 0, 0.5f, 160, 120);
    expectSameImages(robots, 3, overview, 1, 1, "robots, 1 thread");
    expectSameImages(robots, 3, overview, 2, 2, "robots, --aa 2");
    expectSameImages(robots, 9, lookingFrom(Vec3{20, -60, -30}, 10, 30, 0, 0.5f, 160, 120), 2, 1,
                     "camera inside the crowd");
    expectSameImages(robots, 9, lookingFrom(Vec3{0, 900, 0}, 90, 0, 0, 0.4f, 120, 120), 2, 1,
                     "looking straight down");

    // Cameras that ride on objects or look at them (SPEC 9.1, 9.2).
    for (const char* name : {"gallery/pov.f2", "gallery/flyaround.f2", "gallery/catch.f2"}) {
        const SceneDesc gallery = test::sceneFromRepo(name);
        for (double t : {0.0, 55.5})
            expectSameImages(gallery, t, cameraAt(gallery, t).resized(160, 120), 2, 1,
                             std::string(name) + " at " + std::to_string(t));
    }
    // Models (SPEC 10.1) with spot lights riding on their heads (10.2), keys in seconds (10.4).
    for (const char* name :
         {"gallery/desk_lamps.f2", "gallery/windmill.f2", "gallery/clock.f2", "gallery/explainer.f2"}) {
        const SceneDesc gallery = test::sceneFromRepo(name);
        for (double t : {0.0, 29.5})
            expectSameImages(gallery, t, cameraAt(gallery, t).resized(160, 90), 2, 1,
                             std::string(name) + " at " + std::to_string(t));
    }
}

TEST(PrimaryBins, AveragedImagesAreThoseOfTheTreeWalk) {
    // Motion blur: each sub-frame is binned for its own time and camera.
    const SceneDesc scene = test::sceneFromRepo("demo.f2");
    std::vector<SubFrame> subFrames;
    for (double t : {30.0, 30.25, 30.5}) subFrames.push_back({t, cameraAt(scene, t).resized(96, 72)});
    Renderer binned(2), walked(2);
    binned.setPrimaryBinsFrom(0);
    walked.setPrimaryBinsFrom(std::numeric_limits<std::size_t>::max());
    Image a, b;
    binned.renderAveraged(scene, 0, subFrames, a);
    walked.renderAveraged(scene, 0, subFrames, b);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Rgb8)), 0);
}

}  // namespace
}  // namespace f2
