// The camera as a target (SPEC 9.1): keyed poses at fractional frames,
// /look_at in every direction and its degenerate cases, attached cameras.
#include "core/anim/camera_motion.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/render/camera.h"
#include "test_scenes.h"

namespace f2 {
namespace {

using test::sceneFromText;

constexpr float kTol = 1e-4f;

Vec3 forwardOf(const Camera& c) { return c.worldFromCamera.column(2); }
Vec3 upOf(const Camera& c) { return c.worldFromCamera.column(1); }

/// The camera's rotation as the Euler angles it was built from.
void expectRotation(const Camera& c, float rx, float ry, float rz) {
    const Mat3 want = rotationFromEulerDegrees(rx, ry, rz);
    for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        EXPECT_VEC_NEAR(c.worldFromCamera.column(i), want.column(i), kTol);
    }
}

TEST(CameraMotion, WithoutKeysTheCameraIsExactlyTheCameraCommand) {
    const SceneDesc s = sceneFromText("/camera 320 240 0.8 10 20 -300 5 -15 2\n/sphere s 1 0 0 0\n");
    const Camera fixed = Camera::fromDesc(s.camera);
    for (double t : {0.0, 3.5, 1e6}) {
        const Camera c = cameraAt(s, t);
        EXPECT_EQ(c.eye, fixed.eye);
        for (int i = 0; i < 3; ++i) EXPECT_EQ(c.worldFromCamera.row[i], fixed.worldFromCamera.row[i]);
        EXPECT_EQ(c.width, 320);
        EXPECT_EQ(c.height, 240);
        EXPECT_EQ(c.distance, 0.8f);
    }
}

TEST(CameraMotion, KeysAtFractionalFrames) {
    // The key without numbers takes /camera's pose although /camera comes later.
    const SceneDesc s = sceneFromText(
        "/key 0 camera\n"
        "/key 10 camera 100 50 -100 0 90 0\n"
        "/camera 400 300 1 0 0 -100\n");
    EXPECT_EQ(s.lastFrame(), 10);
    const Camera c = cameraAt(s, 2.5);  // u = 1/4
    EXPECT_VEC_NEAR(c.eye, (Vec3{25, 12.5f, -100}), kTol);
    expectRotation(c, 0, 22.5f, 0);
    EXPECT_EQ(c.width, 400);  // size and d do not animate
    EXPECT_EQ(c.distance, 1.0f);
    EXPECT_VEC_NEAR(cameraAt(s, 0).eye, (Vec3{0, 0, -100}), 0);
    EXPECT_VEC_NEAR(cameraAt(s, 20).eye, (Vec3{100, 50, -100}), 0);  // the last key holds
}

TEST(CameraMotion, InterpCameraEasesItsKeys) {
    const SceneDesc s = sceneFromText(
        "/camera 400 300 1 0 0 -100\n"
        "/interp camera ease\n"
        "/anim camera\n"
        "/key 0 camera\n"
        "/key 10 camera 100 50 -100 0 90 0\n");
    // u = 1/4 eased: 0.15625
    const Camera c = cameraAt(s, 2.5);
    EXPECT_VEC_NEAR(c.eye, (Vec3{15.625f, 7.8125f, -100}), kTol);
    expectRotation(c, 0, 14.0625f, 0);
}

/// A camera at the origin with rotation `rot` looking at `point`.
Camera lookingAt(const std::string& point, const std::string& rot = "0 0 0") {
    return cameraAt(sceneFromText("/camera 80 60 1 0 0 0 " + rot + "\n/look_at " + point + "\n"), 0);
}

TEST(CameraMotion, LookAtPointsInSeveralDirections) {
    const float h = std::sqrt(0.5f);
    expectRotation(lookingAt("10 0 10"), 0, 45, 0);  // ry = atan2(10, 10)
    EXPECT_VEC_NEAR(forwardOf(lookingAt("10 0 10")), (Vec3{h, 0, h}), kTol);
    expectRotation(lookingAt("0 10 10"), -45, 0, 0);  // rx = −asin(√½): up is negative rx
    EXPECT_VEC_NEAR(forwardOf(lookingAt("0 10 10")), (Vec3{0, h, h}), kTol);
    expectRotation(lookingAt("0 0 -7"), 0, 180, 0);  // behind: atan2(0, −7)
    expectRotation(lookingAt("-3 0 0"), 0, -90, 0);
    // The keyed rotation is replaced entirely, rz included.
    expectRotation(lookingAt("10 0 10", "30 60 20"), 0, 45, 0);
}

TEST(CameraMotion, LookAtStraightUpOrDownKeepsTheKeyedRy) {
    const Camera down = lookingAt("0 -5 0", "10 30 20");
    expectRotation(down, 90, 30, 0);  // rx = −asin(−1), ry kept, rz = 0
    EXPECT_VEC_NEAR(forwardOf(down), (Vec3{0, -1, 0}), kTol);
    EXPECT_VEC_NEAR(upOf(down), (Vec3{0.5f, 0, std::sqrt(0.75f)}), kTol);  // Ry(30)·(0, 0, 1)
    expectRotation(lookingAt("0 1e-3 0", "0 -40 0"), -90, -40, 0);
}

TEST(CameraMotion, LookAtTheEyeKeepsTheKeyedRotation) {
    const SceneDesc s = sceneFromText("/camera 80 60 1 5 6 7 10 20 30\n/look_at 5 6 7\n");
    expectRotation(cameraAt(s, 0), 10, 20, 30);
}

TEST(CameraMotion, LookAtAMovingObjectAndAPartCentre) {
    const SceneDesc s = sceneFromText(
        "/camera 80 60 1\n"
        "/sphere ball 5 100 0 0\n"
        "/key 0 ball\n"
        "/key 10 ball 0 0 100 0 0 0\n"
        "/look_at ball\n");
    expectRotation(cameraAt(s, 0), 0, 90, 0);
    expectRotation(cameraAt(s, 5), 0, 45, 0);  // ball at (50, 0, 50)
    expectRotation(cameraAt(s, 10), 0, 0, 0);
    // F-2's head box centre: root (0, 0, 100) + body pivot (0, −105, 0) + head
    // pivot (0, 150, 0) + centre (0, 25, 0) = (0, 70, 100): rx = −atan(0.7).
    const SceneDesc r = sceneFromText("/camera 80 60 1\n/robot f2 0 0 100 0 180 0\n/look_at f2.head\n");
    expectRotation(cameraAt(r, 0), -34.992020f, 0, 0);
    EXPECT_VEC_NEAR(lookAtPoint(r, *r.camera.lookAt, 0), (Vec3{0, 70, 100}), kTol);
    // The head turned by a key moves the box centre with it: ry 90 swings the
    // centre (0, 25, 0) about the pivot's y axis, which leaves it in place,
    // so tilt it instead: rx 90 takes (0, 25, 0) to (0, 0, 25) (+y toward +z).
    const SceneDesc tilted =
        sceneFromText("/robot f2 0 0 100\n/key 0 f2.head 0 0 0 90 0 0\n/look_at f2.head\n");
    EXPECT_VEC_NEAR(lookAtPoint(tilted, *tilted.camera.lookAt, 0), (Vec3{0, 45, 125}), kTol);
}

TEST(CameraMotion, AttachedCameraRidesOnAPart) {
    // F-2 at (0, 0, 0) turned ry 90; a camera on his head 10 up and 30 forward.
    // Head frame: (0, 45, 0), axes Ry(90): local +z is world +x.
    const SceneDesc s = sceneFromText(
        "/robot f2 0 0 0 0 90 0\n"
        "/camera 80 60 1 0 10 30\n"
        "/attach camera f2.head\n");
    const Camera c = cameraAt(s, 0);
    EXPECT_VEC_NEAR(c.eye, (Vec3{30, 55, 0}), kTol);
    expectRotation(c, 0, 90, 0);  // looks where F-2 looks
}

TEST(CameraMotion, LookAtSetsTheWorldRotationOfAnAttachedCamera) {
    const SceneDesc s = sceneFromText(
        "/robot f2 0 0 0 0 90 0\n"
        "/camera 80 60 1 0 10 30 0 0 0\n"
        "/attach camera f2.head\n"
        "/look_at 30 55 -100\n");  // straight toward world −z from the eye (30, 55, 0)
    const Camera c = cameraAt(s, 0);
    EXPECT_VEC_NEAR(c.eye, (Vec3{30, 55, 0}), kTol);
    expectRotation(c, 0, 180, 0);
    // Straight above the eye: the world rotation it would have without /look_at.
    const SceneDesc up = sceneFromText(
        "/robot f2 0 0 0 0 90 0\n"
        "/camera 80 60 1 0 10 30 0 0 0\n"
        "/attach camera f2.head\n"
        "/look_at 30 500 0\n");
    expectRotation(cameraAt(up, 0), 0, 90, 0);
}

}  // namespace
}  // namespace f2
