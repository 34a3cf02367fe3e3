// Visibility keys (SPEC 10.7): `/key <t> <target> visible 0|1`, each error at
// its place, always a step, and a hidden target seen by no ray: not drawn,
// no shadow, not reflected, not picked, not exported.
#include <gtest/gtest.h>

#include <string>

#include "core/anim/frame_builder.h"
#include "core/render/camera.h"
#include "core/render/pick.h"
#include "core/render/renderer.h"
#include "core/scene/models.h"
#include "io/frame_primitives.h"
#include "render_paths.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

TEST(VisibleErrors, EachAtItsPlace) {
    const std::string ball = "/sphere ball 1 0 0 0\n";
    test::expectOnlyError(ball + "/key 0 ball visible 2\n", 2, 21, "visible must be 0 or 1, got 2");
    test::expectOnlyError(ball + "/key 0 ball visible 0.5\n", 2, 21, "visible must be 0 or 1, got 0.5");
    test::expectOnlyError(ball + "/key 0 ball visible 1 ease\n", 2, 23,
                          "'visible' keys are always a step: a mode word is not allowed here");
    test::expectOnlyError(ball + "/key 0 ball visible\n", 2, 13, "'visible' takes 1 number (0 or 1), got 0");
    test::expectOnlyError(ball + "/key 0 camera visible 0\n", 2, 15,
                          "'visible' is not a property of the camera");
    test::expectOnlyError("/point_light 1 0 5 0 name l\n" + ball + "/key 0 l visible 0\n", 3, 10,
                          "'visible' is not a property of the light 'l'");
}

TEST(Visible, AlwaysAStepWhateverTheTargetsInterp) {
    const SceneDesc scene = test::sceneFromText(
        "/sphere b 1 0 0 0\n/interp b ease\n/key 0 b visible 1\n/key 10 b visible 0\n/key 20 b visible 1\n"
        "/amb_light 1\n");
    ASSERT_EQ(scene.visibilityTracks.size(), 1u);
    const Track& track = scene.visibilityTracks[0].track;
    EXPECT_TRUE(visibleAt(track, 0));
    EXPECT_TRUE(visibleAt(track, 9.999));
    EXPECT_FALSE(visibleAt(track, 10));
    EXPECT_FALSE(visibleAt(track, 19.5));
    EXPECT_TRUE(visibleAt(track, 20));
    EXPECT_TRUE(visibleAt(track, 1000));
    EXPECT_EQ(scene.lastFrame(), 20);
}

using test::renderText;

// A mirror ball that reflects a red ball, both over a floor lit from above.
constexpr const char* kRoom =
    "/camera 96 64 0.5 0 120 -260 20 0 0\n"
    "/box floor 800 2 800 0 -1 0\n/paint floor 200 200 200\n/material floor 0.2 1 0 1\n"
    "/sphere mirror 40 -60 40 60\n/paint mirror 30 30 30\n/material mirror 0.2 0.5 0 1 0.8\n"
    "/dir_light 1 0.3 -1 0.2\n/amb_light 0.2\n";

TEST(Visible, AHiddenObjectIsSeenByNoRay) {
    // Hidden, the red ball leaves no pixel, no shadow and no reflection: the
    // picture is the room without it, byte for byte.
    const std::string room = kRoom;
    const std::string ball = "/sphere red 25 50 60 20\n/paint red 250 30 30\n/material red 0.2 1 0 1\n";
    const Image without = renderText(room, 0);
    const std::string keyed = room + ball + "/key 0 red visible 1\n/key 10 red visible 0\n";
    EXPECT_TRUE(renderText(keyed, 10).pixels == without.pixels);
    EXPECT_TRUE(renderText(keyed, 15).pixels == without.pixels);
    // Before its hiding key it is there, as if it had no keys.
    EXPECT_TRUE(renderText(keyed, 5).pixels == renderText(room + ball, 0).pixels);
    EXPECT_FALSE(renderText(keyed, 5).pixels == without.pixels);
}

TEST(Visible, APartHidesItsOwnShapesAndAnObjectAllOfThem) {
    const std::string base = std::string(kRoom) + "/robot r 40 105 20 0 180 0\n";
    const SceneDesc scene = test::sceneFromText(base + "/key 0 r.head visible 0\n");
    EvaluatedFrame frame;
    evaluateFrame(scene, 0, frame);
    const ModelType& robot = *robotModel();
    const std::uint32_t first = frame.firstPrimitive[2];
    ASSERT_EQ(frame.rayMask.size(), frame.primitives.size());
    for (std::size_t k = 0; k < robot.shapes.size(); ++k)
        EXPECT_EQ((frame.rayMask[first + k] & ray_mask::kHidden) != 0,
                  robot.shapes[k].part == RobotPart::Head)
            << k;
    // Hiding the robot and showing its head still hides the head: both must show it.
    const SceneDesc both = test::sceneFromText(base + "/key 0 r visible 0\n/key 0 r.head visible 1\n");
    evaluateFrame(both, 0, frame);
    for (std::size_t k = 0; k < robot.shapes.size(); ++k)
        EXPECT_TRUE(frame.rayMask[first + k] & ray_mask::kHidden);
    EXPECT_TRUE(renderText(base + "/key 0 r visible 0\n", 0).pixels == renderText(kRoom, 0).pixels);
}

TEST(Visible, AHiddenTargetIsNotPickedAndNotExported) {
    const std::string text =
        std::string(kRoom) + "/sphere red 25 50 60 20\n/key 0 red visible 1\n/key 4 red visible 0\n";
    const SceneDesc scene = test::sceneFromText(text);
    const Camera camera = cameraAt(scene, 0);
    float px = 0, py = 0;
    ASSERT_TRUE(camera.project(Vec3{50, 60, 20}, px, py));
    const auto shown = pickPixel(scene, 0, camera, int(px), int(py));
    ASSERT_TRUE(shown);
    EXPECT_EQ(shown->object, 2u);
    const auto hidden = pickPixel(scene, 4, camera, int(px), int(py));
    EXPECT_TRUE(!hidden || hidden->object != 2u);
    EXPECT_EQ(framePrimitives(scene, 0).size(), 3u);
    EXPECT_EQ(framePrimitives(scene, 4).size(), 2u);
}

TEST(Visible, PacketPathIdenticalToTheReference) {
    test::expectIdenticalPaths(
        std::string(kRoom) +
            "/sphere red 25 50 60 20\n/material red 0.2 1 0 1\n/key 0 red visible 0\n"
            "/robot r -40 105 -20\n/material r 0.3 1 0 1\n/key 0 r.lhand visible 0\n"
            "/box title 100 20 10 0 150 0\n/no_shadow title\n/material title 1 1 0 1\n",
        "hidden objects, a hidden part, a shadowless title");
}

}  // namespace
}  // namespace f2
