#pragma once
/// Where the camera is and which way it looks at a time (SPEC 2, 9.1, 9.2):
/// its keys, the object it rides on and its `/look_at`.
#include "core/math/transform.h"
#include "core/scene/scene_desc.h"

namespace f2 {

/// The camera's world frame at time `t` (frames): the translation is the eye,
/// the columns of the linear part are its right, up and forward axes. A scene
/// without camera keys, `/attach camera` or `/look_at` gives exactly `/camera`'s
/// pose.
Transform cameraFrameAt(const SceneDesc& scene, double t);

/// The camera's `d` at time t: its `d` keys (SPEC 10.3), else `/camera`'s.
/// An easing that overshoots is kept above zero.
double cameraDistanceAt(const SceneDesc& scene, double t);

/// Euler angles (degrees, SPEC 1) that turn the camera's forward axis to the
/// direction `toPoint` (need not be unit): rx = −asin(f_y), ry = atan2(f_x, f_z),
/// rz = 0. When f_x = f_z = 0 the given `ry` is kept. `toPoint` must not be 0.
Vec3 lookAtRotation(double toX, double toY, double toZ, double ry);

/// The point `/look_at` names, in world space at time t.
Vec3 lookAtPoint(const SceneDesc& scene, const LookAt& lookAt, double t);

}  // namespace f2
