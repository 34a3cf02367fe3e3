// Key-frame animation (SPEC 6) and the model part hierarchy (SPEC 5).
#include <gtest/gtest.h>

#include <cmath>

#include "core/anim/frame_builder.h"
#include "core/anim/track.h"
#include "core/render/camera.h"
#include "robot_parts.h"
#include "test_scenes.h"

namespace f2 {

using test::RobotPart;
namespace {

Track trackOf(std::initializer_list<std::pair<double, float>> keys, Interpolation mode) {
    Track track;
    track.interpolation = mode;
    for (auto [frame, x] : keys) track.keys.push_back({frame, Pose{{x, 0, 0}, {0, 0, 0}}});
    return track;
}

float xAt(const Track& track, double t) { return evaluateTrack(track, t, Pose{{-999, 0, 0}, {}}).position.x; }

TEST(Track, NoKeysStaysAtRest) {
    Pose rest{{1, 2, 3}, {4, 5, 6}};
    EXPECT_EQ(evaluateTrack(Track{}, 7.5, rest), rest);
}

TEST(Track, LinearAtBetweenAndOutsideKeys) {
    Track t = trackOf({{10, 100}, {20, 300}}, Interpolation::Linear);
    EXPECT_FLOAT_EQ(xAt(t, 10), 100);  // at a key
    EXPECT_FLOAT_EQ(xAt(t, 20), 300);
    EXPECT_FLOAT_EQ(xAt(t, 15), 200);    // halfway
    EXPECT_FLOAT_EQ(xAt(t, 12.5), 150);  // fractional time: a quarter of the way
    EXPECT_FLOAT_EQ(xAt(t, 0), 100);     // before the first key the first holds
    EXPECT_FLOAT_EQ(xAt(t, 99), 300);    // after the last the last holds
}

// Regression (issue 13.1): NaN passed every comparison, upper_bound returned
// end() and the segment read one key past the buffer (ASan: heap overflow).
TEST(Track, NonFiniteTimesStayOnTheKeys) {
    for (Interpolation mode : {Interpolation::Linear, Interpolation::Ease, Interpolation::Spline}) {
        Track t = trackOf({{0, 10}, {5, 20}, {10, 30}}, mode);
        EXPECT_FLOAT_EQ(xAt(t, std::nan("")), 10);
        EXPECT_FLOAT_EQ(xAt(t, -std::nan("")), 10);
        EXPECT_FLOAT_EQ(xAt(t, -INFINITY), 10);
        EXPECT_FLOAT_EQ(xAt(t, INFINITY), 30);
    }
}

TEST(Track, LinearInterpolatesAllSixNumbers) {
    Track t;
    t.keys = {{0, Pose{{0, 10, 20}, {0, 90, -40}}}, {4, Pose{{4, 30, 20}, {40, 0, 40}}}};
    Pose p = evaluateTrack(t, 1, Pose{});
    EXPECT_EQ(p.position, (Vec3{1, 15, 20}));
    EXPECT_EQ(p.rotation, (Vec3{10, 67.5f, -20}));
}

TEST(Track, EaseIsSmoothstepOfTheFraction) {
    Track t = trackOf({{0, 0}, {4, 64}}, Interpolation::Ease);
    // u = 1/4: 3/16 - 2/64 = 0.15625 -> 10 of 64
    EXPECT_FLOAT_EQ(xAt(t, 1), 10);
    EXPECT_FLOAT_EQ(xAt(t, 2), 32);  // symmetric about the middle
    // u = 3/4: 27/16 - 54/64 = 0.84375 -> 54
    EXPECT_FLOAT_EQ(xAt(t, 3), 54);
    EXPECT_FLOAT_EQ(xAt(t, 4), 64);
}

TEST(Track, SplinePassesThroughKeys) {
    Track t = trackOf({{0, 0}, {10, 10}, {20, 0}, {30, 10}}, Interpolation::Spline);
    for (int k = 0; k <= 30; k += 10) EXPECT_NEAR(xAt(t, k), k % 20 == 0 ? 0 : 10, 1e-5) << k;
}

TEST(Track, SplineBetweenKeysMatchesCatmullRomByHand) {
    Track t = trackOf({{0, 0}, {10, 10}, {20, 0}, {30, 10}}, Interpolation::Spline);
    // Segment 10..20: P0=0 P1=10 P2=0 P3=10, u=1/2:
    // 1/2 (20 + 0 + (0-50+0-10)/4 + (30-0-0+10)/8) = 1/2 (20 - 15 + 5) = 5
    EXPECT_NEAR(xAt(t, 15), 5, 1e-5);
    // First segment 0..10, the end key stands in for P0: P0=P1=0, P2=10, P3=0, u=1/4:
    // 1/2 (0 + 10/4 + 40/16 - 30/64) = 2.265625
    EXPECT_NEAR(xAt(t, 2.5), 2.265625, 1e-5);
    // Last segment 20..30: P0=10 P1=0 P2=10 P3=P2=10, u=1/2:
    // 1/2 (0 + 0 + (20-0+40-10)/4 + (0-10-30+10)/8) = 1/2 (12.5 - 3.75) = 4.375
    EXPECT_NEAR(xAt(t, 25), 4.375, 1e-5);
}

TEST(Track, SplineHasNoKinkAtAKey) {
    // The slope just before and after the key at 10 agree (linear would not).
    Track t = trackOf({{0, 0}, {10, 10}, {20, 40}}, Interpolation::Spline);
    double h = 1e-3;
    double before = (xAt(t, 10) - xAt(t, 10 - h)) / h;
    double after = (xAt(t, 10 + h) - xAt(t, 10)) / h;
    EXPECT_NEAR(before, after, 0.05);
    EXPECT_NEAR(after, 2.0, 0.05);  // Catmull-Rom tangent (P2 - P0)/2 over 10 frames: 40/2/10
}

TEST(Animation, RobotRightHandPivotAfterTurnAndLean) {
    // Robot at (100, 0, 50) turned ry = 90; its body leans rx = 20 at frame 10.
    SceneDesc scene = test::sceneFromText(
        "/robot r 100 0 50 0 90 0\n"
        "/key 0 r.body\n"
        "/key 10 r.body 0 0 0 20 0 0\n");
    const SceneObject& robot = scene.objects[0];
    auto parts = modelPartFrames(robot, objectFrame(robot, 10), 10);
    // Body pivot (0,-105,0); rhand pivot in body frame (52,140,0) turned by Rx(20):
    //   (52, 140 cos20, 140 sin20) = (52, 131.5570, 47.8828); plus pivot -> (52, 26.5570, 47.8828)
    // Ry(90): x' = z, z' = -x -> (47.8828, 26.5570, -52); plus (100, 0, 50):
    Vec3 pivot = parts[int(RobotPart::RHand)].translation;
    EXPECT_NEAR(pivot.x, 147.8828, 1e-3);
    EXPECT_NEAR(pivot.y, 26.5570, 1e-3);
    EXPECT_NEAR(pivot.z, -2.0, 1e-3);
    // Halfway (frame 5) the lean is 10 degrees: y = -105 + 140 cos10 = 32.8730
    auto half = modelPartFrames(robot, objectFrame(robot, 5), 5);
    EXPECT_NEAR(half[int(RobotPart::RHand)].translation.y, 32.8730, 1e-3);
}

TEST(Animation, PositiveArmRxSwingsBackwardUp) {
    SceneDesc scene = test::sceneFromText("/robot r 0 0 0\n/key 0 r.rhand 0 0 0 90 0 0\n");
    EvaluatedFrame frame;
    evaluateFrame(scene, 0, frame);
    // Primitive order: body, head, left eye, right eye, lhand, rhand. The rhand
    // cylinder centre is 50 below its pivot (52, 35, 0); rx = 90 sends -y to -z.
    Vec3 centre = frame.primitives[5].centre;
    EXPECT_NEAR(centre.x, 52, 1e-4);
    EXPECT_NEAR(centre.y, 35, 1e-4);
    EXPECT_NEAR(centre.z, -50, 1e-4);  // behind the robot, which faces +z
}

TEST(Animation, HeadTurnCarriesTheEyes) {
    SceneDesc scene = test::sceneFromText("/robot r 0 0 0\n/key 0 r.head 0 0 0 0 90 0\n");
    EvaluatedFrame frame;
    evaluateFrame(scene, 0, frame);
    // Head pivot: (0, -105 + 150, 0) = (0, 45, 0). Right eye at (14, 30, 25) in
    // the head frame; Ry(90): x' = z = 25, z' = -x = -14.
    Vec3 eye = frame.primitives[3].centre;
    EXPECT_NEAR(eye.x, 25, 1e-4);
    EXPECT_NEAR(eye.y, 75, 1e-4);
    EXPECT_NEAR(eye.z, -14, 1e-4);
}

TEST(Animation, ModelsExpandToTheirPrimitivesWithColoursAndMaterials) {
    SceneDesc scene = test::sceneFromRepo("seed_example.f2");
    EvaluatedFrame frame;
    evaluateFrame(scene, 0, frame);
    ASSERT_EQ(frame.primitives.size(), 1u + 6u + 4u);
    // The floor is green; the robot default grey; its eyes keep 20 20 20.
    EXPECT_EQ(frame.surfaces[0].color, (Vec3{0, 200 / 255.0f, 0}));
    EXPECT_EQ(frame.surfaces[1].color, (Vec3{200, 200, 200}) / 255.0f);
    EXPECT_EQ(frame.surfaces[3].color, (Vec3{20, 20, 20}) / 255.0f);
    EXPECT_EQ(frame.primitives[1].kind, ShapeKind::Cylinder);
    EXPECT_EQ(frame.primitives[2].kind, ShapeKind::Box);
    EXPECT_EQ(frame.primitives[3].kind, ShapeKind::Sphere);
}

TEST(Animation, EyesTakeTheHeadsMaterialAndKeepTheirColour) {
    SceneDesc scene = test::sceneFromText(
        "/robot r 0 0 0\n/paint r 255 0 0\n/paint r.head 0 0 255\n/material r.head 0.5 0.6 0.7 8\n");
    EvaluatedFrame frame;
    evaluateFrame(scene, 0, frame);
    EXPECT_EQ(frame.surfaces[2].color, (Vec3{20, 20, 20}) / 255.0f);
    EXPECT_EQ(frame.surfaces[2].material, (Material{0.5f, 0.6f, 0.7f, 8}));
    EXPECT_EQ(frame.surfaces[1].color, (Vec3{0, 0, 1}));  // head
    EXPECT_EQ(frame.surfaces[0].color, (Vec3{1, 0, 0}));  // body
    EXPECT_EQ(frame.surfaces[0].material, Material{});
}

TEST(Animation, SeedExampleTurnsTheRobotAndRaisesItsArms) {
    SceneDesc scene = test::sceneFromRepo("seed_example.f2");
    EXPECT_EQ(scene.lastFrame(), 15);
    const SceneObject& robot = scene.objects[1];
    // Frame 2.5: halfway between ry 180 (frame 0) and 135 (frame 5).
    Transform root = objectFrame(robot, 2.5);
    Vec3 forward = root.applyToVector({0, 0, 1});
    double angle = std::atan2(forward.x, forward.z) * 180 / kPi;
    EXPECT_NEAR(angle, 157.5, 1e-3);
    // Frame 10: the left hand is halfway between rest (5) and (120, 45, 0) (15).
    Pose hand = evaluateTrack(robot.partTracks[int(RobotPart::LHand)], 10, Pose{});
    EXPECT_FLOAT_EQ(hand.rotation.x, 60);
    EXPECT_FLOAT_EQ(hand.rotation.y, 22.5f);
}

TEST(Animation, DemoSceneStoryKeepsEveryoneInFrameAndLastsTenSeconds) {
    SceneDesc scene = test::sceneFromRepo("demo.f2");
    EXPECT_GE(scene.lastFrame(), 9 * scene.fps);
    EXPECT_LE(scene.lastFrame(), 11 * scene.fps);
    EvaluatedFrame frame;
    Camera camera = Camera::fromDesc(scene.camera);
    for (int t = 0; t <= scene.lastFrame(); t += 4) {
        evaluateFrame(scene, t, frame);
        // Every primitive but the floor projects inside the image.
        for (std::size_t i = 1; i < frame.primitives.size(); ++i) {
            Vec3 local = camera.worldFromCamera.transposed() * (frame.primitives[i].centre - camera.eye);
            ASSERT_GT(local.z, 0) << "frame " << t << " primitive " << i;
            float x = local.x / local.z * camera.distance, y = local.y / local.z * camera.distance;
            EXPECT_LT(std::fabs(x), 0.5f) << "frame " << t << " primitive " << i;
            EXPECT_LT(std::fabs(y), 0.5f * camera.height / camera.width)
                << "frame " << t << " primitive " << i;
        }
    }
}

}  // namespace
}  // namespace f2
