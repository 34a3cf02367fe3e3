// Point, spot and soft lights (docs/scene-language.md, docs/rendering.md):
// the commands as parsed, the shading formulas at chosen pixels, the packet
// path against the reference path, and determinism of soft shadows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "core/anim/light_evaluation.h"
#include "core/render/pixel_report.h"
#include "core/render/renderer.h"
#include "io/bench_scenes.h"
#include "render_paths.h"
#include "test_scenes.h"

namespace f2 {
namespace {

TEST(LightCommands, PointAndSpotLightsAreKeptAsWritten) {
    SceneDesc s = test::sceneFromText(
        "/sphere s 10 0 0 0\n"
        "/point_light 0.5 1 2 3\n"
        "/point_light 0.25 0 100 0 size 20 4 fade 50 2\n"
        "/spot_light 0.75 0 200 0 0 -1 0 20 30 tightness 3 fade 100 1 size 10 2\n"
        "/dir_light 0.6 0 -1 1 angle 2 3\n");
    ASSERT_EQ(s.localLights.size(), 3u);
    EXPECT_EQ(s.localLights[0].kind, LocalLightKind::Point);
    EXPECT_EQ(s.localLights[0].position, (Vec3{1, 2, 3}));
    EXPECT_FALSE(s.localLights[0].fade.fades());
    EXPECT_FALSE(s.localLights[0].area.soft());
    EXPECT_EQ(s.localLights[1].fade, (Fade{50, 2}));
    EXPECT_EQ(s.localLights[1].area, (SoftShadow{20, 4}));
    const LocalLight& spot = s.localLights[2];
    EXPECT_EQ(spot.kind, LocalLightKind::Spot);
    EXPECT_EQ(spot.direction, (Vec3{0, -1, 0}));
    EXPECT_FLOAT_EQ(spot.radius, 20);
    EXPECT_FLOAT_EQ(spot.falloff, 30);
    EXPECT_FLOAT_EQ(spot.tightness, 3);
    EXPECT_EQ(spot.fade, (Fade{100, 1}));
    EXPECT_EQ(spot.area, (SoftShadow{10, 2}));
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].sun, (SoftShadow{2, 3}));
}

TEST(LightCommands, BadOptionsAreErrorsAtTheirPlace) {
    test::expectOnlyError("/point_light 1 0 0 0 soft 2\n", 1, 22,
                          "unknown option 'soft' of '/point_light' (expected 'fade', 'size' or 'name')");
    test::expectOnlyError("/point_light 1 0 0 0 fade 1 2 fade 1 2\n", 1, 31, "second 'fade' option");
    test::expectOnlyError("/point_light 1 0 0 0 size 20\n", 1, 22,
                          "'size' takes a diameter and the samples per side");
    test::expectOnlyError("/point_light 1 0 0 0 size 20 32\n", 1, 30,
                          "samples per side must be a whole number from 2 to 16, got 32");
    test::expectOnlyError("/point_light 1 0 0 0 fade 0 2\n", 1, 27, "fade distance must be > 0, got 0");
    test::expectOnlyError("/dir_light 1 0 -1 0 angle 60 4\n", 1, 27,
                          "angular radius must be at most 45 degrees, got 60");
    test::expectOnlyError("/dir_light 1 0 -1 0 size 1 4\n", 1, 21,
                          "unknown option 'size' of '/dir_light' (expected 'angle' or 'name')");
    test::expectOnlyError("/spot_light 1 0 0 0 0 -1 0 30 20\n", 1, 28,
                          "spot radius must be at most its falloff (20), got 30");
    test::expectOnlyError("/spot_light 1 0 0 0 0 -1 0 10 120\n", 1, 31,
                          "spot falloff must be at most 90 degrees, got 120");
    test::expectOnlyError("/spot_light 1 0 0 0 0 0 0 10 20\n", 1, 21, "light direction must not be 0 0 0");
    test::expectOnlyError("/spot_light 1 0 0 0 0 -1 0 10\n", 1, 1, "'/spot_light' takes 9 arguments, got 8");
    test::expectOnlyError("/point_light 1 0 0 0 fade 1 2 fade 1 2 fade 1 2 fade 1 2 fade 1 2 fade 1 2\n", 1,
                          1, "'/point_light' takes at most 19 arguments with its options, got 22");
}

TEST(LightCommands, TheDiscPatternIsPovRaysCircularGrid) {
    std::vector<DiscPoint> disc;
    appendDiscPattern(4, disc);
    ASSERT_EQ(disc.size(), 16u);
    for (const DiscPoint& p : disc) {
        // Every point within the unit-diameter disc (the grid is shifted by 0.001, as POV-Ray's).
        EXPECT_LE(std::hypot(p.u, p.v), 0.5011f);
    }
    EXPECT_NEAR(std::hypot(disc[0].u, disc[0].v), 0.499, 1e-6);
    std::set<std::pair<float, float>> distinct;
    for (const DiscPoint& p : disc) distinct.insert({p.u, p.v});
    EXPECT_EQ(distinct.size(), 16u);
}

/// The story of pixel (x, y) of `text`'s scene at frame 0.
PixelReport pixelOf(const char* text, int x, int y) {
    SceneDesc scene = test::sceneFromText(text);
    Renderer renderer(1);
    Image image;
    Camera camera = Camera::fromDesc(scene.camera);
    renderer.render(scene, 0, camera, image);
    return tracePixel(renderer.frame(), camera, x, y);
}

// A grey floor seen from above; the light's part of a pixel must be the
// formula of docs/scene-language.md, worked out here in double.
constexpr const char* kFloor =
    "/camera 64 48 0.5 0 300 0 90 0 0\n"
    "/box floor 2000 10 2000 0 -5 0\n/paint floor 255 255 255\n/material floor 0 1 0 1\n";

double lambert(const PixelReport& r, Vec3 light) {
    Vec3 p = r.surface.shadowOrigin;
    double dx = light.x - p.x, dy = light.y - p.y, dz = light.z - p.z;
    double d = std::sqrt(dx * dx + dy * dy + dz * dz);
    return std::max(0.0, (double(r.surface.normal.x) * dx + double(r.surface.normal.y) * dy +
                          double(r.surface.normal.z) * dz) /
                             d);
}

TEST(LightShading, PointLightWithFadeFollowsPovRaysFormula) {
    std::string text = std::string(kFloor) + "/point_light 0.9 40 100 30 fade 80 2\n";
    for (auto [x, y] : {std::pair{32, 24}, {10, 40}, {60, 5}}) {
        PixelReport r = pixelOf(text.c_str(), x, y);
        ASSERT_TRUE(r.hit);
        Vec3 p = r.surface.shadowOrigin;
        double d = std::hypot(40.0 - p.x, 100.0 - p.y, 30.0 - p.z);
        double expected = 0.9 * 2 / (1 + std::pow(d / 80, 2)) * lambert(r, {40, 100, 30});
        EXPECT_NEAR(r.color.x, expected, 1e-5) << x << "," << y;
        ASSERT_EQ(r.lights.size(), 1u);
        EXPECT_FALSE(r.lights[0].term.shadowed);
    }
}

TEST(LightShading, SpotLightHasPovRaysConeAndTightness) {
    // Straight down from 200 above the floor: angle θ at the floor point p.
    std::string text = std::string(kFloor) + "/spot_light 1 0 200 0 0 -1 0 10 25 tightness 2\n";
    int inside = 0, edge = 0, outside = 0;
    for (int y = 0; y < 48; y += 3)
        for (int x = 0; x < 64; x += 3) {
            PixelReport r = pixelOf(text.c_str(), x, y);
            ASSERT_TRUE(r.hit);
            Vec3 p = r.surface.shadowOrigin;
            double d = std::hypot(double(p.x), 200.0 - p.y, double(p.z));
            double cosAngle = (200.0 - p.y) / d;
            double cone = 1;
            double cosRadius = std::cos(10 * std::numbers::pi / 180),
                   cosFalloff = std::cos(25 * std::numbers::pi / 180);
            if (cosAngle < cosFalloff) {
                cone = 0, ++outside;
            } else if (cosAngle < cosRadius) {
                double u = (cosAngle - cosFalloff) / (cosRadius - cosFalloff);
                cone = (3 - 2 * u) * u * u, ++edge;
            } else {
                ++inside;
            }
            double expected = cosAngle * cosAngle * cone * lambert(r, {0, 200, 0});
            EXPECT_NEAR(r.color.x, expected, 1e-4) << x << "," << y;
        }
    EXPECT_GT(inside, 0);
    EXPECT_GT(edge, 0);
    EXPECT_GT(outside, 0);
}

// A ball over the floor between it and the light: the shadow is the ball's
// silhouette seen from the light, and only points nearer than the light count.
constexpr const char* kBallUnderLight =
    "/camera 64 48 2 0 300 0 90 0 0\n"
    "/box floor 2000 10 2000 0 -5 0\n/material floor 0 1 0 1\n"
    "/sphere ball 20 0 60 0\n";

TEST(LightShading, PointLightsCastShadowsOnlyFromBetween) {
    // Light above the ball: the floor below it is in shadow.
    PixelReport below = pixelOf((std::string(kBallUnderLight) + "/point_light 1 0 150 0\n").c_str(), 32, 24);
    ASSERT_EQ(below.lights.size(), 1u);
    // The pixel at the image centre sees the top of the ball, not the floor.
    EXPECT_EQ(below.chosen.primitive, 1u);
    PixelReport floor = pixelOf((std::string(kBallUnderLight) + "/point_light 1 0 150 0\n").c_str(), 32, 36);
    ASSERT_EQ(floor.chosen.primitive, 0u);
    EXPECT_TRUE(floor.lights[0].term.shadowed) << floor.surface.position;
    // A light between the ball and the floor: the ball is beyond it, no shadow.
    PixelReport lit = pixelOf((std::string(kBallUnderLight) + "/point_light 1 0 30 0\n").c_str(), 32, 36);
    ASSERT_EQ(lit.chosen.primitive, 0u);
    EXPECT_FALSE(lit.lights[0].term.shadowed) << lit.surface.position;
}

TEST(LightShading, SoftShadowsHaveAPenumbra) {
    // The shadow of the ball under a soft point light and a soft sun: along a
    // row through it, the visible fraction goes from 1 through values
    // between to 0 (umbra) and back, in steps of 1/16.
    for (const char* light : {"/point_light 1 0 150 0 size 40 4\n", "/dir_light 1 0 -1 0 angle 15 4\n"}) {
        SceneDesc scene = test::sceneFromText(std::string(kBallUnderLight) + light);
        Renderer renderer(1);
        Image image;
        Camera camera = Camera::fromDesc(scene.camera);
        renderer.render(scene, 0, camera, image);
        std::set<float> fractions;
        for (int x = 0; x < 64; ++x) {
            PixelReport r = tracePixel(renderer.frame(), camera, x, 33);
            if (!r.hit || r.chosen.primitive != 0) continue;
            float visible = r.lights[0].term.shadowed ? 0.0f : r.lights[0].term.visible;
            EXPECT_EQ(visible * 16, std::floor(visible * 16)) << light << x;
            fractions.insert(visible);
        }
        EXPECT_TRUE(fractions.contains(1.0f)) << light;
        EXPECT_GE(fractions.size(), 4u) << light << ": a penumbra of several levels";
    }
}

TEST(LightShading, SoftShadowsAreTheSameForAnyThreadCount) {
    SceneDesc scene = test::sceneFromText(
        "/camera 160 120 0.6 0 200 -300 30 0 0\n/box floor 800 10 800 0 -5 0\n"
        "/robot r 0 0 0 0 160 0\n/sphere s 25 -90 60 30\n/amb_light 0.2\n"
        "/dir_light 0.6 0.5 -1 0.3 angle 4 4\n/point_light 0.5 100 200 -50 size 50 3\n");
    Image one, two;
    Renderer a(1), b(2);
    Camera camera = Camera::fromDesc(scene.camera);
    a.render(scene, 0, camera, one);
    b.render(scene, 0, camera, two);
    EXPECT_TRUE(one.pixels == two.pixels);
}

using test::expectIdenticalPaths;

constexpr const char* kStage =
    "/camera 203 149 0.6 30 180 -300 25 -5 0\n"
    "/box floor 800 20 800 0 -10 100 0 10 0\n/material floor 1 1 0 1\n"
    "/box tilted 60 40 80 -60 30 100 20 35 -10\n/material tilted 1 1 0 1\n"
    "/cylinder c 25 90 40 45 80 70 0 30\n/material c 1 1 0 1\n"
    "/sphere s 30 90 40 150\n/material s 0.5 0.8 0 1\n"
    "/robot r 0 0 220 0 200 0\n/material r 1 1 0 1\n"
    "/amb_light 0.1\n";

TEST(LightPacketPath, IdenticalToTheReferenceForEveryLightKind) {
    const std::string stage = kStage;
    expectIdenticalPaths(stage + "/point_light 0.8 -100 250 0\n/point_light 0.5 200 80 -50 fade 200 1.5\n",
                         "point lights");
    expectIdenticalPaths(stage +
                             "/spot_light 0.9 0 300 50 0.1 -1 0.3 15 30\n"
                             "/spot_light 0.7 -200 150 -100 1 -0.6 1 5 40 tightness 3 fade 300 2\n",
                         "spot lights");
    expectIdenticalPaths(stage + "/dir_light 0.7 0.4 -1 0.5 angle 3 4\n/dir_light 0.3 -1 -1 0\n", "soft sun");
    expectIdenticalPaths(stage +
                             "/point_light 0.6 -80 220 20 size 40 4\n"
                             "/spot_light 0.6 150 250 -30 -0.4 -1 0.3 20 35 size 30 3 fade 250 2\n",
                         "soft point and spot");
}

/// With highlights the packet path's pow() may round one level apart (docs/design.md).
void expectPathsWithinOneLevel(const SceneDesc& scene, const std::string& what) {
    Renderer renderer(2);
    Image fast, reference;
    Camera camera = Camera::fromDesc(scene.camera);
    renderer.render(scene, 0, camera, fast);
    traceReference(renderer.frame(), camera, reference);
    int worst = 0;
    for (std::size_t i = 0; i < fast.pixels.size(); ++i) {
        Rgb8 a = fast.pixels[i], b = reference.pixels[i];
        worst = std::max({worst, std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
    }
    EXPECT_LE(worst, 1) << what;
}

TEST(LightPacketPath, WithinOneLevelOfTheReferenceWithHighlights) {
    expectPathsWithinOneLevel(
        test::sceneFromText(
            "/camera 160 120 0.6 30 180 -300 25 -5 0\n/box floor 800 20 800 0 -10 100\n"
            "/sphere s 40 0 40 100\n/material s 1 1 0.8 20\n/robot r 100 0 150 0 200 0\n/amb_light 0.1\n"
            "/point_light 0.6 -80 220 20 size 40 4\n/spot_light 0.6 150 250 -30 -0.4 -1 0.3 20 35\n"
            "/dir_light 0.5 0.3 -1 0.6 angle 2 4\n"),
        "highlights");
    // Hundreds of robots: a soft sun's shadow packets start from the deep
    // nodes that one of its sample directions reaches from each tile.
    BenchSceneSpec spec;
    spec.shape = BenchShape::Robots;
    spec.count = 400;
    expectPathsWithinOneLevel(
        test::sceneFromText(benchSceneText(spec, 200, 150) + "/dir_light 0.4 -0.2 -1 0.5 angle 4 4\n"),
        "400 robots under a soft sun");
}

}  // namespace
}  // namespace f2
