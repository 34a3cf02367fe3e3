// The generated benchmark scenes robots:N, spheres:N and lamps:N (io/bench_scenes.h):
// they parse, hold what docs/performance.md says, animate, and the camera
// formula keeps every object in view.
#include "io/bench_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/anim/frame_builder.h"
#include "core/render/camera.h"
#include "core/render/renderer.h"
#include "test_scenes.h"

namespace f2 {
namespace {

TEST(BenchScenes, ParsesSpecs) {
    BenchSceneSpec spec;
    std::string error;
    ASSERT_TRUE(parseBenchSceneSpec("robots:1000", spec, error)) << error;
    EXPECT_EQ(spec.shape, BenchShape::Robots);
    EXPECT_EQ(spec.count, 1000);
    ASSERT_TRUE(parseBenchSceneSpec("spheres:7", spec, error)) << error;
    EXPECT_EQ(spec.shape, BenchShape::Spheres);
    EXPECT_EQ(spec.count, 7);
    EXPECT_EQ(benchSceneName(spec), "spheres:7");
    ASSERT_TRUE(parseBenchSceneSpec("lamps:1000", spec, error)) << error;
    EXPECT_EQ(spec.shape, BenchShape::Lamps);
    EXPECT_EQ(spec.count, 1000);
    EXPECT_EQ(benchSceneName(spec), "lamps:1000");
    for (const char* bad : {"robots", "robots:", "robots:0", "robots:-3", "robots:1.5", "robots:12x",
                            "cubes:4", "robots:1000001", "", "lamps:0", "lamps:1001"}) {
        EXPECT_FALSE(parseBenchSceneSpec(bad, spec, error)) << bad;
        EXPECT_FALSE(error.empty()) << bad;
    }
    // A light per lamp: SPEC 7's 1,000 lights are the limit, and the message says so.
    EXPECT_FALSE(parseBenchSceneSpec("lamps:1001", spec, error));
    EXPECT_EQ(error,
              "N in 'lamps:1001' must be a whole number 1..1000 (a light per lamp; at most 1000 lights, "
              "SPEC 7)");
}

TEST(BenchScenes, GridIsCeilSqrtColumns) {
    auto grid = [](int n) {
        BenchGrid g = benchGrid(n);
        return std::pair{g.columns, g.rows};
    };
    EXPECT_EQ(grid(1), std::pair(1, 1));
    EXPECT_EQ(grid(2), std::pair(2, 1));
    EXPECT_EQ(grid(10), std::pair(4, 3));
    EXPECT_EQ(grid(100), std::pair(10, 10));
    EXPECT_EQ(grid(101), std::pair(11, 10));
    EXPECT_EQ(grid(10000), std::pair(100, 100));
}

TEST(BenchScenes, RobotsParseAndAnimate) {
    for (int n : {1, 10, 100}) {
        SceneDesc scene = test::sceneFromText(benchSceneText({BenchShape::Robots, n}));
        EXPECT_EQ(scene.primitiveCount(), std::size_t(1 + 6 * n)) << n;  // floor + robots
        EXPECT_EQ(scene.lastFrame(), kBenchSwingFrames);
        EXPECT_EQ(scene.lights.size(), 1u);
        EXPECT_FLOAT_EQ(scene.ambient, 0.2f);
        // The arms move between frames, so evaluation and the BVH differ per frame.
        EvaluatedFrame a, b;
        evaluateFrame(scene, 0.0, a);
        evaluateFrame(scene, 6.0, b);
        ASSERT_EQ(a.primitives.size(), b.primitives.size());
        EXPECT_FALSE(a.primitives.back().centre == b.primitives.back().centre) << n;
    }
}

TEST(BenchScenes, SpheresParse) {
    SceneDesc scene = test::sceneFromText(benchSceneText({BenchShape::Spheres, 100}));
    EXPECT_EQ(scene.primitiveCount(), 101u);
    EXPECT_EQ(scene.objects[1].size.x, 50.0f);
}

TEST(BenchScenes, LampsParseAnimateAndLightTheFloor) {
    SceneDesc scene = test::sceneFromText(benchSceneText({BenchShape::Lamps, 3}));
    EXPECT_EQ(scene.primitiveCount(), std::size_t(1 + 8 * 3));  // floor + 8 shapes a lamp
    EXPECT_EQ(scene.lastFrame(), kBenchSwingFrames);
    EXPECT_EQ(scene.lights.size(), 0u);  // only the lamps' own lights
    EXPECT_EQ(scene.localLights.size(), 3u);
    EXPECT_EQ(scene.lightMotions.size(), 3u);
    EXPECT_FLOAT_EQ(scene.ambient, 0.0f);
    // The heads nod between frames.
    EvaluatedFrame a, b;
    evaluateFrame(scene, 0.0, a);
    evaluateFrame(scene, 6.0, b);
    ASSERT_EQ(a.primitives.size(), b.primitives.size());
    EXPECT_FALSE(a.primitives.back().centre == b.primitives.back().centre);
    // A small frame is not black: the pools of light on the floor and the glowing bulbs.
    Renderer renderer(2);
    Image image;
    renderer.render(scene, 6.0, cameraAt(scene, 6.0).resized(80, 60), image, {1});
    // (Measured: 545 of the 4800 pixels above 150, the background being 20 + 22 + 30.)
    int lit = 0;
    for (const Rgb8& p : image.pixels) lit += p.r + p.g + p.b > 150;
    EXPECT_GT(lit, 200);
    // 1,000 lamps are 1,000 lights, within SPEC 7's limit.
    EXPECT_EQ(test::sceneFromText(benchSceneText({BenchShape::Lamps, 1000})).localLights.size(), 1000u);
}

TEST(BenchScenes, TextIsDeterministicAndSized) {
    EXPECT_EQ(benchSceneText({BenchShape::Robots, 50}), benchSceneText({BenchShape::Robots, 50}));
    SceneDesc scene = test::sceneFromText(benchSceneText({BenchShape::Spheres, 3}, 320, 200));
    EXPECT_EQ(scene.camera.width, 320);
    EXPECT_EQ(scene.camera.height, 200);
}

/// Projects p with the SPEC 2 camera; true if it lands inside the image.
bool inView(const Camera& camera, Vec3 p) {
    Vec3 v = camera.worldFromCamera.transposed() * (p - camera.eye);
    if (v.z <= 0) return false;
    float x = v.x / v.z * camera.distance, y = v.y / v.z * camera.distance;
    float halfHeight = 0.5f * float(camera.height) / float(camera.width);
    return std::abs(x) <= 0.5f && std::abs(y) <= halfHeight;
}

TEST(BenchScenes, CameraSeesEveryGridCell) {
    for (int n : {1, 10, 100, 1000, 10000}) {
        SceneDesc scene = test::sceneFromText(benchSceneText({BenchShape::Robots, n}));
        Camera camera = Camera::fromDesc(scene.camera);
        BenchGrid grid = benchGrid(n);
        float hx = float(grid.columns * kBenchSpacing / 2), hz = float(grid.rows * kBenchSpacing / 2);
        // Corners of the box around all cells, from the floor to the robots' heads.
        for (float x : {-hx, hx})
            for (float y : {-105.0f, 95.0f})
                for (float z : {-hz, hz})
                    EXPECT_TRUE(inView(camera, {x, y, z})) << n << ": " << Vec3{x, y, z};
    }
}

}  // namespace
}  // namespace f2
