// Scene language, second edition, SPEC 9.1-9.3: the camera as a target,
// /look_at, /attach and interpolation modes per key; each rule's error at its
// exact line and column.
#include <gtest/gtest.h>

#include "core/parse/language.h"
#include "core/parse/parser.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

using test::sceneFromText;

constexpr const char* kFile = "m.f2";

using test::expectOnlyError;

constexpr const char* kTwo = "/sphere a 1 0 0 0\n/robot r 0 0 0\n";

// 9.1 The camera is a target
TEST(ParserCamera, KeysInterpAndAnimOfTheCamera) {
    const SceneDesc s = sceneFromText(
        "/anim camera\n/interp camera spline\n/key 0 camera 1 2 3 4 5 6 step\n/key 7 camera\n"
        "/camera 80 60 1 9 8 7 6 5 4\n");
    const Track& t = s.camera.track;
    EXPECT_EQ(t.interpolation, Interpolation::Spline);
    ASSERT_EQ(t.keys.size(), 2u);
    EXPECT_EQ(t.keys[0].pose, (Pose{{1, 2, 3}, {4, 5, 6}}));
    EXPECT_EQ(t.keys[0].mode, Interpolation::Step);
    EXPECT_EQ(t.keys[1].pose, (Pose{{9, 8, 7}, {6, 5, 4}}));  // /camera's pose, given later
    EXPECT_EQ(s.camera.pose, (Pose{{9, 8, 7}, {6, 5, 4}}));
    EXPECT_EQ(s.lastFrame(), 7);
}

TEST(ParserCamera, RestKeyWithoutCameraCommandIsTheDefaultPose) {
    const SceneDesc s = sceneFromText("/key 3 camera\n");
    ASSERT_EQ(s.camera.track.keys.size(), 1u);
    EXPECT_EQ(s.camera.track.keys[0].pose, Pose{});
}

TEST(ParserCamera, RepeatedCameraKeyWarnsAtItsPlace) {
    const ParseResult r = parseScene(
        "/key 2 camera 1 1 1 0 0 0\n/camera 80 60 1\n/key 2 camera\n/sphere s 1 0 0 0\n/amb_light 1\n",
        kFile);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].format(),
              "m.f2:3:6: warning: key frame 2 of 'camera' is given again; it replaces the key at 1:6");
    EXPECT_EQ(r.scene->camera.track.keys[0].pose, Pose{});  // the later key, /camera's pose
}

TEST(ParserCamera, CameraIsNotAName) {
    expectOnlyError("/sphere camera 1 0 0 0\n", 1, 9, "'camera' is the name of the scene camera");
    expectOnlyError("/robot camera 0 0 0\n", 1, 8, "'camera' is the name of the scene camera");
}

TEST(ParserCamera, CameraIsNotATargetOfPaintMaterialLookAtOrAttach) {
    expectOnlyError("/paint camera 1 1 1\n", 1, 8, "'/paint' does not apply to the camera");
    expectOnlyError("/material camera 1 1 1 1\n", 1, 11, "'/material' does not apply to the camera");
    expectOnlyError("/look_at camera\n", 1, 10, "'/look_at' does not apply to the camera");
    expectOnlyError("/sphere a 1 0 0 0\n/attach a camera\n", 2, 11, "'/attach' does not apply to the camera");
}

TEST(ParserCamera, TheCameraHasNoParts) {
    expectOnlyError("/key 0 camera.head\n", 1, 15, "the camera has no parts");
    expectOnlyError("/anim camera head\n", 1, 14, "the camera has no parts");
    expectOnlyError("/interp camera.lhand ease\n", 1, 16, "the camera has no parts");
}

TEST(ParserCamera, LookAtAPointAnObjectOrAPart) {
    EXPECT_EQ(sceneFromText("/look_at 1 2 3\n").camera.lookAt->point, (Vec3{1, 2, 3}));
    const SceneDesc s = sceneFromText(std::string(kTwo) + "/look_at r.rhand\n");
    ASSERT_TRUE(s.camera.lookAt && s.camera.lookAt->target);
    EXPECT_EQ(*s.camera.lookAt->target, (FrameRef{1, int(RobotPart::RHand)}));
    EXPECT_FALSE(sceneFromText("/fps 24\n").camera.lookAt.has_value());
}

TEST(ParserCamera, LookAtErrors) {
    expectOnlyError("/look_at 1 2 3\n/look_at 4 5 6\n", 2, 1, "second '/look_at' (the first is at 1:1)");
    expectOnlyError("/look_at 1 2\n", 1, 1, "'/look_at' takes 1 or 3 arguments, got 2");
    expectOnlyError("/look_at 1 x 3\n", 1, 12, "expected a number, got 'x'");
    expectOnlyError("/look_at nobody\n", 1, 10, "unknown name 'nobody'");
    expectOnlyError("/look_at a.head\n/sphere a 1 0 0 0\n", 1, 10, "unknown name 'a'");  // earlier lines only
    expectOnlyError("/sphere a 1 0 0 0\n/look_at a.head\n", 2, 12, "on a part of a primitive");
}

// 9.2 Attachments
TEST(ParserAttach, ObjectsAndTheCameraRideOnObjectsOrParts) {
    const SceneDesc s = sceneFromText(std::string(kTwo) + "/attach a r.lhand\n/attach camera a\n");
    EXPECT_EQ(s.objects[0].attachedTo, (FrameRef{1, int(RobotPart::LHand)}));
    EXPECT_FALSE(s.objects[1].attachedTo.has_value());
    EXPECT_EQ(s.camera.attachedTo, (FrameRef{0, -1}));
    ASSERT_EQ(s.attachOrder.size(), 1u);
    EXPECT_EQ(s.attachOrder[0], 0u);
}

TEST(ParserAttach, Errors) {
    const std::string two(kTwo);
    expectOnlyError(two + "/attach a\n", 3, 1, "'/attach' takes 2 or 4 arguments, got 1");
    expectOnlyError(two + "/attach b r\n", 3, 9, "unknown name 'b'");
    expectOnlyError(two + "/attach a nobody.head\n", 3, 11, "unknown name 'nobody'");
    // Both names on earlier lines: a target created later is unknown here.
    expectOnlyError("/sphere a 1 0 0 0\n/attach a late.head\n/robot late 0 0 0\n", 2, 11,
                    "unknown name 'late'");
    expectOnlyError("/robot r 0 0 0\n/attach early r\n/sphere early 1 0 0 0\n", 2, 9, "unknown name 'early'");
    expectOnlyError(two + "/attach a r.leg\n", 3, 13, "unknown part 'leg'");
    expectOnlyError(two + "/attach r.head a\n", 3, 9, "only a whole object or the camera can be attached");
    expectOnlyError(two + "/attach a r\n/attach a r.head\n", 4, 9, "'a' is already attached (at 3:1)");
    expectOnlyError(two + "/attach camera a\n/attach camera r\n", 4, 9,
                    "'camera' is already attached (at 3:1)");
    expectOnlyError(two + "/attach a a\n", 3, 1, "'a' cannot be attached to itself");
    expectOnlyError(two + "/attach r r.head\n", 3, 1, "'r' cannot be attached to its own part");
    expectOnlyError(two + "/attach a r\n/attach r a\n", 4, 1,
                    "attaching 'r' to 'a' makes a cycle: 'a' already rides on 'r'");
    // A longer cycle is found at the /attach that closes it.
    expectOnlyError(two + "/sphere c 1 0 0 0\n/attach a r\n/attach r c\n/attach c a\n", 6, 1,
                    "attaching 'c' to 'a' makes a cycle: 'a' already rides on 'c'");
    expectOnlyError(two + "/sphere c 1 0 0 0\n/attach c a\n/attach r a\n/attach a r.rhand\n", 6, 1,
                    "attaching 'a' to 'r.rhand' makes a cycle: 'r' already rides on 'a'");
}

TEST(ParserAttach, TreesWithoutCyclesAreFine) {
    const SceneDesc s = sceneFromText(
        "/sphere a 1 0 0 0\n/sphere b 1 0 0 0\n/sphere c 1 0 0 0\n/sphere d 1 0 0 0\n"
        "/attach d c\n/attach b a\n/attach c a\n/attach camera d\n");
    // Each attached object after the attached object it rides on.
    ASSERT_EQ(s.attachOrder.size(), 3u);
    std::vector<int> position(4, -1);
    for (std::size_t k = 0; k < s.attachOrder.size(); ++k) position[s.attachOrder[k]] = int(k);
    EXPECT_LT(position[2], position[3]);  // c before d
    EXPECT_GE(position[1], 0);
}

// 9.3 Interpolation per key
TEST(ParserModes, EveryModeWordOnKeysAndInterp) {
    for (std::string_view word : {"linear", "ease", "ease_in", "ease_out", "step", "spline", "back",
                                  "elastic", "bounce", "bezier 0.25 0.1 0.25 1"}) {
        const std::string w(word);
        const SceneDesc s = sceneFromText("/robot r 0 0 0\n/interp r " + w + "\n/key 0 r " + w +
                                          "\n/key 1 r.head 0 0 0 1 2 3 " + w + "\n");
        EXPECT_EQ(easingText(s.objects[0].track.interpolation), word);
        EXPECT_EQ(easingText(*s.objects[0].track.keys[0].mode), word);
        EXPECT_EQ(easingText(*s.objects[0].partTracks[std::size_t(RobotPart::Head)].keys[0].mode), word);
    }
}

TEST(ParserModes, Errors) {
    const std::string a = "/sphere a 1 0 0 0\n";
    expectOnlyError(a + "/key 0 a 1 2 3 4 5 6 wobble\n", 2, 22,
                    "unknown interpolation 'wobble' (expected linear, ease, ease_in, ease_out, step, spline, "
                    "back, elastic, bounce or bezier)");
    expectOnlyError(a + "/key 0 a Ease\n", 2, 10, "unknown interpolation 'Ease'");  // lower case only
    expectOnlyError(a + "/interp a easein\n", 2, 11, "unknown interpolation 'easein'");
    expectOnlyError("/interp camera wobble\n", 1, 16, "unknown interpolation 'wobble'");
    expectOnlyError(a + "/key 0 a 1 2 3 ease\n", 2, 1, "'/key' takes 0 or 6 numbers after the target, got 3");
    expectOnlyError(a + "/key 0 a 1 2 3 4 5 6 7\n", 2, 1,
                    "'/key' takes 0 or 6 numbers after the target, got 7");
    expectOnlyError(a + "/key 0 a ease ease\n", 2, 1, "'/key' takes 0 or 6 numbers after the target, got 1");
    // Longer than any key: its last word is past the stored tokens (found by the fuzzer).
    expectOnlyError(a + "/key 0 a 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 ease\n", 2, 1,
                    "'/key' takes 0 or 6 numbers after the target, got 18");
}

// 10.4 bezier x1 y1 x2 y2: its numbers, their ranges, and where each error points.
TEST(ParserModes, BezierErrors) {
    const std::string a = "/sphere a 1 0 0 0\n";
    expectOnlyError(a + "/key 0 a bezier\n", 2, 10, "'bezier' takes 4 numbers after it (x1 y1 x2 y2), got 0");
    expectOnlyError(a + "/key 0 a 1 2 3 4 5 6 bezier 0 0\n", 2, 22,
                    "'bezier' takes 4 numbers after it (x1 y1 x2 y2), got 2");
    expectOnlyError(a + "/interp a bezier 0 0 1\n", 2, 1, "'/interp' takes 2 or 6 arguments, got 5");
    expectOnlyError(a + "/interp a ease 0 0 1 1\n", 2, 11, "'ease' takes no numbers after it, got 4");
    expectOnlyError(a + "/key 0 a bezier 1.5 0 1 1\n", 2, 17, "bezier's x1 must be from 0 to 1, got 1.5");
    expectOnlyError(a + "/interp a bezier 0 0 -0.1 1\n", 2, 22, "bezier's x2 must be from 0 to 1, got -0.1");
    expectOnlyError(a + "/key 0 a bezier 0 y 1 1\n", 2, 19, "expected a number, got 'y'");
    // y may leave [0, 1] (an overshoot, as in CSS).
    const SceneDesc s = sceneFromText(a + "/key 0 a bezier 0.3 -0.5 0.7 1.5\n");
    EXPECT_EQ(s.objects[0].track.keys[0].mode, (Easing{Interpolation::Bezier, {0.3f, -0.5f, 0.7f, 1.5f}}));
    // Seconds stand only where a key time does.
    expectOnlyError("/sphere a 2s 0 0 0\n", 1, 11,
                    "a time in seconds ('2s') stands only where a key time does; here a number is expected");
    expectOnlyError("/sphere a (1+1)s 0 0 0\n", 1, 11,
                    "a time in seconds ('(1+1)s') stands only where a key time does");
}

}  // namespace
}  // namespace f2
