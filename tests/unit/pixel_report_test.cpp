// tracePixel(): the story of one pixel must be the reference path's own
// computation, told completely.
#include "core/render/pixel_report.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/render/renderer.h"
#include "test_scenes.h"

namespace f2 {
namespace {

// A ball over a floor, lit straight down and from the side: the floor under
// the ball is in its shadow for the first light only.
constexpr const char* kBallOverFloor =
    "/camera 80 60 0.5 0 100 -200 30 0 0\n"
    "/box floor 1000 10 1000 0 -5 0\n/paint floor 100 150 200\n"
    "/sphere ball 20 0 60 0\n/robot r 150 0 100 0 0 0\n"
    "/amb_light 0.3\n/dir_light 0.6 0 -1 0\n/dir_light 0.3 -1 -1 0\n";

struct Rendered {
    SceneDesc scene;
    Renderer renderer{1};
    Camera camera;
    Image reference;
    explicit Rendered(const char* text)
        : scene(test::sceneFromText(text)), camera(Camera::fromDesc(scene.camera)) {
        Image packet;
        renderer.render(scene, 0, camera, packet);
        traceReference(renderer.frame(), camera, reference);
    }
};

TEST(PixelReport, EveryPixelIsTheReferencePathsPixel) {
    Rendered r(kBallOverFloor);
    int hits = 0, shadowed = 0;
    for (int y = 0; y < r.camera.height; y += 3)
        for (int x = 0; x < r.camera.width; x += 3) {
            PixelReport report = tracePixel(r.renderer.frame(), r.camera, x, y);
            ASSERT_EQ(report.pixel, r.reference.at(x, y)) << x << "," << y;
            if (!report.hit) {
                EXPECT_TRUE(report.crossings.empty()) << x << "," << y;
                continue;
            }
            ++hits;
            // The chosen hit is the first crossing: nearest, ties by index.
            ASSERT_FALSE(report.crossings.empty());
            EXPECT_EQ(report.crossings.front().primitive, report.chosen.primitive) << x << "," << y;
            EXPECT_EQ(report.crossings.front().t, report.chosen.t) << x << "," << y;
            for (std::size_t i = 1; i < report.crossings.size(); ++i)
                EXPECT_LE(report.crossings[i - 1].t, report.crossings[i].t);
            // One term per light, and the terms add up to the colour's diffuse part.
            ASSERT_EQ(report.lights.size(), 2u);
            float diffuse = report.ambientTerm;
            for (const PixelReport::Light& l : report.lights) {
                diffuse += l.term.diffuse;
                if (l.term.shadowed) {
                    ++shadowed;
                    EXPECT_NE(l.occluder, Bvh::kNoPrimitive) << "a shadow names its occluder";
                    EXPECT_EQ(l.term.diffuse, 0.0f);
                }
            }
            EXPECT_NEAR(report.color.x,
                        report.surfaceColor.x * diffuse + report.lights[0].term.specular +
                            report.lights[1].term.specular,
                        1e-5f);
        }
    EXPECT_GT(hits, 100);
    EXPECT_GT(shadowed, 3);
}

TEST(PixelReport, TheFloorUnderTheBallIsInItsShadow) {
    Rendered r(kBallOverFloor);
    // The pixels that see the floor just under the ball (0, 0, 0).
    int found = 0;
    for (int y = 0; y < r.camera.height; ++y)
        for (int x = 0; x < r.camera.width; ++x) {
            PixelReport report = tracePixel(r.renderer.frame(), r.camera, x, y);
            // Within 12 of it: inside the ball's shadow (radius 20), a pixel or two wide.
            const Vec3 p = report.surface.position;
            if (!report.hit || std::fabs(p.y) > 0.01f || std::fabs(p.x) > 12 || std::fabs(p.z) > 12) continue;
            ++found;
            EXPECT_EQ(primitiveName(r.scene, r.renderer.frame(), report.chosen.primitive), "floor (box)");
            EXPECT_EQ(report.surface.normal, (Vec3{0, 1, 0}));
            ASSERT_EQ(report.lights.size(), 2u);
            EXPECT_TRUE(report.lights[0].term.shadowed) << "the light from straight above";
            EXPECT_EQ(primitiveName(r.scene, r.renderer.frame(), report.lights[0].occluder), "ball (sphere)");
            // The ball's underside above p: radius 20 around (0, 60, 0).
            EXPECT_NEAR(report.lights[0].occluderT, 60 - std::sqrt(400 - p.x * p.x - p.z * p.z), 0.01);
            EXPECT_FALSE(report.lights[1].term.shadowed) << "the side light passes beside the ball";
        }
    EXPECT_GT(found, 0) << "no pixel sees the floor under the ball";
}

TEST(PixelReport, NamesModelParts) {
    Rendered r(kBallOverFloor);
    const PreparedFrame& frame = r.renderer.frame();
    // floor, ball, then the robot's six shapes in the model's order.
    ASSERT_EQ(frame.primitives.size(), 8u);
    EXPECT_EQ(primitiveName(r.scene, frame, 0), "floor (box)");
    EXPECT_EQ(primitiveName(r.scene, frame, 1), "ball (sphere)");
    EXPECT_EQ(primitiveName(r.scene, frame, 2).rfind("r.body", 0), 0u) << primitiveName(r.scene, frame, 2);
    EXPECT_EQ(primitiveName(r.scene, frame, 8), "?");
}

TEST(PixelReport, CoincidentSurfacesAreAllListedAndTheFirstWins) {
    Rendered r(
        "/camera 40 30 0.5\n/box a 50 50 50 0 0 200\n/paint a 255 0 0\n"
        "/box b 50 50 50 0 0 200\n/paint b 0 255 0\n/amb_light 1\n");
    PixelReport report = tracePixel(r.renderer.frame(), r.camera, 20, 15);
    ASSERT_EQ(report.crossings.size(), 2u);
    EXPECT_EQ(report.crossings[0].t, report.crossings[1].t);
    EXPECT_EQ(report.chosen.primitive, 0u) << "a tie goes to the first in the scene";
    EXPECT_EQ(report.pixel, (Rgb8{255, 0, 0}));
}

}  // namespace
}  // namespace f2
