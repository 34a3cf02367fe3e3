// Named lights that move (SPEC 10.2) and keys of every property (10.3):
// each error at its place, the values a frame takes between keys, and the
// pictures they make.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/anim/frame_builder.h"
#include "core/anim/light_evaluation.h"
#include "core/render/camera.h"
#include "core/render/renderer.h"
#include "core/scene/models.h"
#include "render_paths.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

TEST(NamedLightErrors, EachAtItsPlace) {
    test::expectOnlyError("/sphere ball 1 0 0 0\n/point_light 1 0 3 0 name ball\n", 2, 27,
                          "duplicate name 'ball' (first defined at 1:9)");
    test::expectOnlyError("/point_light 1 0 3 0 name lamp\n/sphere lamp 1 0 0 0\n", 2, 9,
                          "duplicate name 'lamp' (first defined at 1:27)");
    test::expectOnlyError("/amb_light 0.1 name sky\n/key 0 sky 1 2 3 0 0 0\n", 2, 8,
                          "'sky' is an ambient light: it has no pose");
    test::expectOnlyError("/dir_light 1 0 -1 0 name sun\n/key 0 sun.head\n", 2, 12, "a light has no parts");
    test::expectOnlyError("/dir_light 1 0 -1 0 name sun\n/paint sun 1 2 3\n", 2, 8,
                          "'/paint' does not apply to lights: 'sun' is a light");
    test::expectOnlyError("/dir_light 1 0 -1 0 name sun\n/look_at sun\n", 2, 10,
                          "'/look_at' does not apply to lights");
    test::expectOnlyError("/dir_light 1 0 -1 0 name sun\n/anim sun head\n", 2, 11, "a light has no parts");
    test::expectOnlyError("/amb_light 0.1 name sky\n/sphere ball 1 0 0 0\n/attach sky ball\n", 3, 9,
                          "'sky' is an ambient light: it has no position, so it cannot be attached");
    test::expectOnlyError("/dir_light 1 0 -1 0 name sun\n/sphere ball 1 0 0 0\n/attach ball sun\n", 3, 14,
                          "'/attach' does not apply to lights");
    test::expectOnlyError("/point_light 1 0 0 0 name l\n/sphere b 1 0 0 0\n/attach l b\n/attach l b\n", 4, 9,
                          "'l' is already attached (at 3:1)");
    test::expectOnlyError("/spot_light 1 0 0 0 0 0 1 10 20 name\n", 1, 33, "'name' takes a new name");
    test::expectOnlyError("/amb_light 1 name 3x\n", 1, 19, "invalid name '3x'");
    test::expectOnlyError("/point_light 1 0 0 0 name l name m\n", 1, 29, "second 'name' option");
    test::expectOnlyError("/point_light 1 0 0 0 name camera\n", 1, 27,
                          "'camera' is the name of the scene camera");
    // Named or not, the ambient lights as written add up to one finite sum.
    test::expectOnlyError("/amb_light 3e38\n/amb_light 3e38 name sky\n", 2, 12,
                          "total ambient intensity is out of range");
    test::expectOnlyError("/amb_light 3e38 name sky\n/amb_light 3e38\n", 2, 12,
                          "total ambient intensity is out of range");
}

TEST(NamedLights, KeyedAmbientsThatOverflowSaturateInsteadOfMakingNaN) {
    // Each key is in range; their sum is not. A surface with ka 0 stays unlit.
    const std::string text =
        "/camera 8 8 0.5 0 0 -10\n/sphere ball 3 0 0 0\n/material ball 0 1 0 1\n"
        "/amb_light 1 name a\n/key 0 a intensity 3e38\n/amb_light 1 name b\n/key 0 b intensity 3e38\n";
    const SceneDesc scene = test::sceneFromText(text);
    EXPECT_EQ(ambientAt(scene, 0), std::numeric_limits<float>::max());
    Renderer renderer(1);
    Image image;
    const Camera camera = cameraAt(scene, 0);
    renderer.render(scene, 0, camera, image);
    Image reference;
    traceReference(renderer.frame(), camera, reference);
    EXPECT_EQ(image.at(4, 4), (Rgb8{0, 0, 0}));
    EXPECT_TRUE(image.pixels == reference.pixels);
}

TEST(PropertyKeyErrors, EachAtItsPlace) {
    const std::string ball = "/sphere ball 1 0 0 0\n";
    test::expectOnlyError(ball + "/key 0 ball colur 1 2 3\n", 2, 13,
                          "unknown key property 'colur' (did you mean 'colour'?)");
    test::expectOnlyError(ball + "/key 0 ball colour 1 2\n", 2, 13,
                          "'colour' takes 3 numbers (r g b), got 2");
    test::expectOnlyError(ball + "/key 0 ball colour\n", 2, 13, "'colour' takes 3 numbers (r g b), got 0");
    test::expectOnlyError(ball + "/key 0 ball colour 1 2 300\n", 2, 24,
                          "blue must be from 0 to 255, got 300");
    test::expectOnlyError(ball + "/key 0 ball colour -1 2 3\n", 2, 20, "red must be from 0 to 255, got -1");
    test::expectOnlyError(ball + "/key 0 ball intensity 2\n", 2, 13,
                          "'intensity' is not a property of the sphere 'ball'");
    test::expectOnlyError(ball + "/key 0 ball d 2\n", 2, 13, "'d' is not a property of the sphere 'ball'");
    test::expectOnlyError("/dir_light 1 0 -1 0 name sun\n" + ball + "/key 0 sun colour 1 2 3\n", 3, 12,
                          "'colour' is not a property of the light 'sun'");
    test::expectOnlyError(ball + "/key 0 camera colour 1 2 3\n", 2, 15,
                          "'colour' is not a property of the camera");
    test::expectOnlyError(ball + "/key 0 camera d 0\n", 2, 17, "screen distance must be > 0, got 0");
    test::expectOnlyError("/point_light 1 0 0 0 name l\n" + ball + "/key 0 l intensity -1\n", 3, 20,
                          "light intensity must be >= 0");
    test::expectOnlyError(ball + "/key 0 ball colour 1 2 3 smooth\n", 2, 26,
                          "unknown interpolation 'smooth'");
    // A lone word after the target is still read as a (mistyped) mode.
    test::expectOnlyError(ball + "/key 0 ball Ease\n", 2, 13, "unknown interpolation 'Ease'");
}

TEST(PropertyKeys, TheyKeepTheirTrackRules) {
    const ParseResult r = parseScene(
        "/sphere ball 1 0 0 0\n/key 4 ball colour 1 2 3\n/key 4 ball colour 4 5 6\n/amb_light 1\n", "t.f2");
    ASSERT_TRUE(r.ok()) << test::formatDiagnostics(r);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].loc.line, 3);
    EXPECT_NE(r.diagnostics[0].message.find("key frame 4 of the colour of 'ball' is given again"),
              std::string::npos)
        << r.diagnostics[0].message;
    ASSERT_EQ(r.scene->colourTracks.size(), 1u);
    ASSERT_EQ(r.scene->colourTracks[0].track.keys.size(), 1u);
    EXPECT_EQ(r.scene->colourTracks[0].track.keys[0].pose.position, (Vec3{4, 5, 6}));
    EXPECT_EQ(r.scene->lastFrame(), 4);
}

// A bulb riding on a ball that moves, a turning sun, and keyed intensities,
// at frame 5 of 0..10: halfway everywhere.
constexpr const char* kMovingLights =
    "/sphere ball 1 0 0 0\n"
    "/point_light 2 0 3 0 name bulb\n"
    "/attach bulb ball\n"
    "/key 0 ball 0 0 0 0 0 0\n/key 10 ball 10 0 0 0 0 0\n"
    "/key 0 bulb intensity 2\n/key 10 bulb intensity 4\n"
    "/dir_light 1 0 0 1 name sun\n"
    "/key 0 sun 0 0 0 0 0 0\n/key 10 sun 0 0 0 0 90 0\n"
    "/amb_light 0.1\n"
    "/amb_light 0.2 name sky\n/key 0 sky intensity 0.2\n/key 10 sky intensity 0.6\n";

TEST(NamedLights, MoveRideAndChangeTheirIntensity) {
    const SceneDesc scene = test::sceneFromText(kMovingLights);
    ASSERT_EQ(scene.lightMotions.size(), 3u);
    EvaluatedFrame frame;
    evaluateFrame(scene, 5, frame);
    ASSERT_EQ(frame.localLights.size(), 1u);
    EXPECT_VEC_NEAR(frame.localLights[0].position, (Vec3{5, 3, 0}), 1e-5f);
    EXPECT_FLOAT_EQ(frame.localLights[0].intensity, 3.0f);
    // SPEC 1: ry 45 turns +z toward +x; L is the way back to the light.
    ASSERT_EQ(frame.lights.size(), 1u);
    const float h = float(std::sqrt(0.5));
    EXPECT_VEC_NEAR(frame.lights[0].toLight, (Vec3{-h, 0, -h}), 1e-6f);
    EXPECT_NEAR(frame.ambient, 0.1f + 0.4f, 1e-6f);
    // Before the first key and after the last the ends hold.
    evaluateFrame(scene, 20, frame);
    EXPECT_VEC_NEAR(frame.localLights[0].position, (Vec3{10, 3, 0}), 1e-5f);
    EXPECT_FLOAT_EQ(frame.localLights[0].intensity, 4.0f);
    EXPECT_VEC_NEAR(frame.lights[0].toLight, (Vec3{-1, 0, 0}), 1e-6f);
}

TEST(NamedLights, TheInterpOfALightReachesItsIntensity) {
    const SceneDesc scene = test::sceneFromText(
        "/sphere b 1 0 0 0\n/point_light 1 0 5 0 name l\n/interp l step\n"
        "/key 0 l intensity 1\n/key 10 l intensity 3\n");
    EvaluatedFrame frame;
    evaluateFrame(scene, 9, frame);
    EXPECT_FLOAT_EQ(frame.localLights[0].intensity, 1.0f);
    evaluateFrame(scene, 10, frame);
    EXPECT_FLOAT_EQ(frame.localLights[0].intensity, 3.0f);
}

TEST(NamedLights, AnOvershootingEasingNeverMakesALightNegative) {
    const SceneDesc scene = test::sceneFromText(
        "/sphere b 1 0 0 0\n/point_light 1 0 5 0 name l\n"
        "/key 0 l intensity 1 back\n/key 10 l intensity 0\n");
    EvaluatedFrame frame;
    for (int t = 0; t <= 10; ++t) {
        evaluateFrame(scene, t, frame);
        EXPECT_GE(frame.localLights[0].intensity, 0.0f) << "frame " << t;
    }
}

using test::renderText;

constexpr const char* kFloorAndBall =
    "/camera 96 64 0.5 0 40 -60 30 0 0\n"
    "/box floor 200 2 200 0 -1 0\n/paint floor 200 200 200\n"
    "/sphere ball 4 0 4 0\n/paint ball 250 80 40\n/amb_light 0.1\n";

TEST(NamedLights, ANameAloneChangesNoPixel) {
    const std::string base = kFloorAndBall;
    EXPECT_TRUE(renderText(base + "/point_light 1 20 30 -10 fade 40 2\n", 0).pixels ==
                renderText(base + "/point_light 1 20 30 -10 fade 40 2 name lamp\n", 0).pixels);
    EXPECT_TRUE(renderText(base + "/dir_light 0.8 1 -1 1\n", 0).pixels ==
                renderText(base + "/dir_light 0.8 1 -1 1 name sun\n", 0).pixels);
}

TEST(NamedLights, ALampCarriedByAMovingBallLightsWhereTheBallIs) {
    // A faint lamp just above the ball: the floor is lit only near it.
    const std::string scene = std::string(kFloorAndBall) +
                              "/point_light 1 0 6 0 fade 10 3 name lamp\n/attach lamp ball\n"
                              "/key 0 ball\n/key 10 ball 30 0 0 0 0 0\n";
    const Image start = renderText(scene, 0), end = renderText(scene, 10);
    EXPECT_FALSE(start.pixels == end.pixels);
    // A floor point right of the ball's start: brighter once the ball is there.
    const SceneDesc parsed = test::sceneFromText(scene);
    float px = 0, py = 0;
    ASSERT_TRUE(cameraAt(parsed, 0).project(Vec3{22, 0, 6}, px, py));
    const Rgb8 before = start.at(int(px), int(py)), after = end.at(int(px), int(py));
    EXPECT_GT(int(after.r), int(before.r) + 20) << "before " << int(before.r) << " after " << int(after.r);
}

Vec3 toUnit(Color8 c) { return Vec3{float(c.r), float(c.g), float(c.b)} / 255.0f; }

TEST(ColourKeys, MostSpecificTargetWinsAndPaintedEyesStay) {
    const SceneDesc scene = test::sceneFromText(
        "/robot r 0 0 0\n/key 0 r colour 0 0 0\n/key 10 r colour 200 100 50\n"
        "/key 0 r.head colour 255 255 255\n/sphere s 1 0 0 0\n/interp s step\n"
        "/key 0 s colour 0 0 0\n/key 10 s colour 255 0 0\n/amb_light 1\n");
    EvaluatedFrame frame;
    evaluateFrame(scene, 5, frame);
    const ModelType& robot = *robotModel();
    for (std::size_t k = 0; k < robot.shapes.size(); ++k) {
        const ModelShape& shape = robot.shapes[k];
        const Vec3 expected = shape.ownColor                  ? toUnit(shape.look.color)
                              : shape.part == RobotPart::Head ? Vec3{1, 1, 1}
                                                              : Vec3{100, 50, 25} / 255.0f;
        SCOPED_TRACE(k);
        EXPECT_VEC_NEAR(frame.surfaces[frame.firstPrimitive[0] + k].color, expected, 1e-6f);
    }
    // `/interp s step` holds the first colour until the next key.
    EXPECT_EQ(frame.surfaces[frame.firstPrimitive[1]].color, (Vec3{0, 0, 0}));
    evaluateFrame(scene, 10, frame);
    EXPECT_EQ(frame.surfaces[frame.firstPrimitive[1]].color, (Vec3{1, 0, 0}));
}

TEST(ColourKeys, AMidFrameShowsTheBlendUnrounded) {
    // Lit by ambient light alone with ka 1, kd 0, ks 0: a pixel is the colour.
    const std::string scene =
        "/camera 32 32 0.5 0 0 -10\n/sphere s 3 0 0 0\n/material s 1 0 0 1\n/amb_light 1\n"
        "/key 0 s colour 255 0 0\n/key 10 s colour 0 0 255\n/key 0 camera d 0.5\n";
    const Rgb8 mid = renderText(scene, 5).at(16, 16);
    EXPECT_EQ(mid.g, 0);
    EXPECT_EQ(mid.r, mid.b);
    EXPECT_GE(mid.r, 127);
    EXPECT_LE(mid.r, 128);
    const Rgb8 start = renderText(scene, 0).at(16, 16);
    EXPECT_EQ(start.r, 255);
    EXPECT_EQ(start.b, 0);
}

TEST(ZoomKeys, TheCameraDistanceFollowsItsKeys) {
    const std::string text =
        "/camera 64 48 0.5 0 0 -10\n/sphere s 1 0 0 0\n/amb_light 1\n"
        "/key 0 camera d 0.5\n/key 10 camera d 1.5 ease\n/key 20 camera d 1.5\n";
    const SceneDesc scene = test::sceneFromText(text);
    EXPECT_FLOAT_EQ(cameraAt(scene, 0).distance, 0.5f);
    EXPECT_FLOAT_EQ(cameraAt(scene, 5).distance, 1.0f);  // ease is symmetric about its middle
    EXPECT_FLOAT_EQ(cameraAt(scene, 15).distance, 1.5f);
    // A longer lens shows the sphere larger: more of the picture is lit.
    const auto lit = [](const Image& image) {
        int n = 0;
        for (const Rgb8& p : image.pixels) n += p.r > 0;
        return n;
    };
    EXPECT_GT(lit(renderText(text, 10)), 2 * lit(renderText(text, 0)));
}

}  // namespace
}  // namespace f2
