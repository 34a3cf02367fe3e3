// Glow and shadowless objects (SPEC 10.8): `emit` in `/material` and
// `/no_shadow`, each error at its place, the colour a glow adds, shadows that
// are not cast while the object is still seen, and the packet path against
// the reference path.
#include <gtest/gtest.h>

#include <string>

#include "core/render/camera.h"
#include "core/render/pixel_report.h"
#include "core/render/renderer.h"
#include "core/render/shading.h"
#include "core/scene/models.h"
#include "io/pov_export.h"
#include "render_paths.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

TEST(GlowErrors, EachAtItsPlace) {
    const std::string ball = "/sphere ball 1 0 0 0\n";
    test::expectOnlyError(ball + "/material ball 1 1 0 1 emit\n", 2, 24, "'emit' takes a number");
    test::expectOnlyError(ball + "/material ball 1 1 0 1 emit -2\n", 2, 29, "emission must be >= 0, got -2");
    test::expectOnlyError(ball + "/material ball 1 1 0 1 0.5 emit x2\n", 2, 33,
                          "expected a number, got 'x2'");
    // A line far longer than a /material (the fuzzer's find: its last tokens are not stored).
    std::string longLine = ball + "/material ball";
    for (int i = 0; i < 24; ++i) longLine += " 1";
    test::expectOnlyError(longLine + "\n", 2, 1, "'/material' takes 5 or 6 arguments, got 25");
    test::expectOnlyError(longLine + " emit 1\n", 2, 1, "'/material' takes 5 or 6 arguments, got 27");
    // Without `emit` the count is read as before.
    test::expectOnlyError(ball + "/material ball 1 1 0 1 1 1\n", 2, 1,
                          "'/material' takes 5 or 6 arguments, got 7");
    test::expectOnlyError(ball + "/material ball 1 1 0 1 glow 1\n", 2, 1,
                          "'/material' takes 5 or 6 arguments, got 7");
}

TEST(NoShadowErrors, EachAtItsPlace) {
    test::expectOnlyError("/sphere ball 1 0 0 0\n/no_shadow\n", 2, 1, "'/no_shadow' takes 1 argument, got 0");
    test::expectOnlyError("/sphere ball 1 0 0 0\n/no_shadow ball ball\n", 2, 1, "takes 1 argument, got 2");
    test::expectOnlyError("/sphere ball 1 0 0 0\n/no_shadow bal\n", 2, 12,
                          "unknown name 'bal' (did you mean 'ball'?)");
    test::expectOnlyError("/sphere ball 1 0 0 0\n/no_shadow camera\n", 2, 12, "does not apply to the camera");
    test::expectOnlyError("/point_light 1 0 9 0 name lamp\n/no_shadow lamp\n", 2, 12,
                          "'/no_shadow' does not apply to lights: 'lamp' is a light");
    test::expectOnlyError("/robot r 0 0 0\n/no_shadow r.tail\n", 2, 14, "");
}

TEST(Glow, IsReadIntoTheMaterialAndNoShadowIntoTheLook) {
    const SceneDesc s = test::sceneFromText(
        "/sphere a 1 0 0 0\n/material a 1 1 0 1 emit 2\n/sphere b 1 0 0 0\n/material b 1 1 0 1 0.5 emit "
        "0.25\n"
        "/robot r 0 0 0\n/no_shadow r.head\n/no_shadow a\n/amb_light 1\n");
    EXPECT_EQ(s.objects[0].appearance[0].material.emission, 2.0f);
    EXPECT_EQ(s.objects[0].appearance[0].material.reflection, 0.0f);
    EXPECT_EQ(s.objects[1].appearance[0].material.emission, 0.25f);
    EXPECT_EQ(s.objects[1].appearance[0].material.reflection, 0.5f);
    EXPECT_FALSE(s.objects[0].appearance[0].castsShadow);
    EXPECT_TRUE(s.objects[1].appearance[0].castsShadow);
    const ModelType& robot = *s.objects[2].model;
    for (std::size_t k = 0; k < robot.shapes.size(); ++k)
        EXPECT_EQ(s.objects[2].appearance[k].castsShadow, robot.shapes[k].part != RobotPart::Head) << k;
}

using test::renderText;

TEST(Glow, AddsEmitTimesTheColourWhateverTheLights) {
    // No light at all: the sphere's centre pixel is e · C alone.
    const std::string sphere =
        "/camera 32 32 0.5 0 0 -10\n/sphere s 3 0 0 0\n/paint s 200 100 50\n/material s 0 1 0 1 emit 0.5\n";
    const Rgb8 alone = renderText(sphere).at(16, 16);
    EXPECT_EQ(alone.r, toByte(200 / 255.0f * 0.5f));
    EXPECT_EQ(alone.g, toByte(100 / 255.0f * 0.5f));
    EXPECT_EQ(alone.b, toByte(50 / 255.0f * 0.5f));
    // With an ambient light and ka 1: C · (Ia + e), clamped at 1.
    const Rgb8 lit = renderText(sphere + "/amb_light 0.7\n/material s 1 1 0 1 emit 0.6\n").at(16, 16);
    EXPECT_EQ(lit.r, 255);
    EXPECT_EQ(lit.g, toByte(100 / 255.0f * 1.3f));
    EXPECT_EQ(lit.b, toByte(50 / 255.0f * 1.3f));
    // emit 0 is the material without it, byte for byte.
    EXPECT_TRUE(
        renderText(sphere + "/amb_light 0.7\n/material s 1 1 0.3 20\n/dir_light 1 1 -1 1\n").pixels ==
        renderText(sphere + "/amb_light 0.7\n/material s 1 1 0.3 20 emit 0\n/dir_light 1 1 -1 1\n").pixels);
}

// A floor lit from straight above, a box hovering over it: its shadow is below it.
constexpr const char* kBoxOverFloor =
    "/camera 64 48 0.5 0 200 -150 50 0 0\n"
    "/box floor 400 2 400 0 -1 0\n/paint floor 200 200 200\n/material floor 0 1 0 1\n"
    "/box b 40 10 40 0 60 0\n/paint b 250 40 40\n/material b 0.3 1 0 1\n"
    "/amb_light 0.2\n/dir_light 1 0 -1 0\n";

TEST(NoShadow, TheObjectIsSeenButItsShadowIsGone) {
    const std::string scene = kBoxOverFloor;
    const SceneDesc parsed = test::sceneFromText(scene);
    float sx = 0, sy = 0, bx = 0, by = 0;
    ASSERT_TRUE(cameraAt(parsed, 0).project(Vec3{0, 0, -10}, sx, sy));  // the floor in the box's shadow
    ASSERT_TRUE(cameraAt(parsed, 0).project(Vec3{0, 65, 0}, bx, by));   // the box's top
    const Image shadowed = renderText(scene), shadowless = renderText(scene + "/no_shadow b\n");
    const std::string noBox =
        "/camera 64 48 0.5 0 200 -150 50 0 0\n"
        "/box floor 400 2 400 0 -1 0\n/paint floor 200 200 200\n/material floor 0 1 0 1\n"
        "/amb_light 0.2\n/dir_light 1 0 -1 0\n";
    const Image empty = renderText(noBox);
    // In shadow with the box; lit as if it were not there without its shadow.
    EXPECT_LT(shadowed.at(int(sx), int(sy)).r, 60);
    EXPECT_EQ(shadowless.at(int(sx), int(sy)), empty.at(int(sx), int(sy)));
    // The box itself is still drawn, lit the same.
    EXPECT_EQ(shadowless.at(int(bx), int(by)), shadowed.at(int(bx), int(by)));
    EXPECT_GT(int(shadowless.at(int(bx), int(by)).r), 200);
}

TEST(NoShadow, APartOfAModelAlone) {
    // F-2 under a low light from the side: only his head stops casting a shadow.
    const std::string scene =
        "/camera 96 72 0.5 0 300 -250 50 0 0\n/box floor 600 2 600 0 -1 0\n/material floor 0 1 0 1\n"
        "/robot r 0 105 0\n/amb_light 0.1\n/dir_light 1 1 -1 0\n";
    const Image all = renderText(scene), headless = renderText(scene + "/no_shadow r.head\n"),
                none = renderText(scene + "/no_shadow r\n");
    std::size_t changedByHead = 0, changedByAll = 0;
    for (std::size_t i = 0; i < all.pixels.size(); ++i) {
        changedByHead += !(all.pixels[i] == headless.pixels[i]);
        changedByAll += !(all.pixels[i] == none.pixels[i]);
    }
    EXPECT_GT(changedByHead, 0u);
    EXPECT_GT(changedByAll, changedByHead);
}

TEST(GlowAndNoShadow, PacketPathIdenticalToTheReference) {
    const std::string scene =
        std::string(kBoxOverFloor) +
        "/sphere bulb 15 60 80 30\n/paint bulb 255 230 150\n/material bulb 0 0 0 1 emit 1.2\n"
        "/no_shadow bulb\n/point_light 0.8 60 80 30\n/no_shadow b\n"
        "/robot r -80 105 40\n/no_shadow r.lhand\n/material r 0.2 1 0 1 0.3 emit 0.1\n";
    test::expectIdenticalPaths(scene, "glow, a light inside a shadowless bulb, a shadowless part");
    // The bulb holds the light inside it and still lights the floor.
    const SceneDesc parsed = test::sceneFromText(scene);
    Renderer renderer(1);
    Image image;
    const Camera camera = cameraAt(parsed, 0);
    renderer.render(parsed, 0, camera, image);
    float fx = 0, fy = 0;
    ASSERT_TRUE(camera.project(Vec3{60, 0, 0}, fx, fy));
    const PixelReport r = tracePixel(renderer.frame(), camera, int(fx), int(fy));
    ASSERT_EQ(r.lights.size(), 2u);
    EXPECT_FALSE(r.lights[1].term.shadowed);
    EXPECT_GT(r.lights[1].term.diffuse, 0.0f);
}

TEST(GlowAndNoShadow, PovRayExportSaysEmissionAndNoShadow) {
    const SceneDesc scene = test::sceneFromText(
        "/sphere bulb 15 0 80 0\n/material bulb 0 0 0 1 emit 1.5\n/no_shadow bulb\n/sphere s 1 0 0 0\n"
        "/amb_light 0.1\n");
    const std::string pov = povScene(scene, 0, cameraAt(scene, 0), {});
    EXPECT_NE(pov.find("emission 1.5 }\n  no_shadow\n}"), std::string::npos) << pov;
    EXPECT_EQ(pov.find("no_shadow", pov.find("// s")), std::string::npos) << pov;
}

}  // namespace
}  // namespace f2
