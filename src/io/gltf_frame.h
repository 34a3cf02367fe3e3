#pragma once
/// F2's frame (SPEC 1: left-handed, +y up, +z away from the default camera)
/// in glTF's (right-handed, +Y up, a camera looking down its -Z): z is
/// mirrored. A point p becomes S·p with S = diag(1, 1, -1), a rigid transform
/// T becomes S·T·S (a rotation's matrix conjugated by the mirror: its axis
/// mirrored, its sense reversed), so products of transforms stay products and
/// a model facing the F2 camera faces the glTF one. F2's camera looks along
/// its +z, which S·T·S turns into glTF's -Z: the camera needs no extra turn.
#include <array>

#include "core/math/transform.h"

namespace f2 {

/// A node's translation and rotation (unit quaternion x, y, z, w) in glTF's frame.
struct GltfPose {
    std::array<float, 3> translation{};
    std::array<float, 4> rotation{0, 0, 0, 1};
};

/// A point or direction of F2's frame in glTF's.
constexpr Vec3 gltfFromF2(Vec3 v) { return {v.x, v.y, -v.z}; }

/// Unit quaternion (x, y, z, w) of a rotation matrix (Shepperd's method:
/// the largest of the four candidates, so no cancellation).
std::array<float, 4> quaternionOf(const Mat3& rotation);

/// The pose of S·T·S (see above).
GltfPose gltfPoseOf(const Transform& f2Transform);

/// `q` or -q (the same rotation), whichever is nearer `previous`, so that
/// interpolating between consecutive samples takes the short way.
std::array<float, 4> continuousQuaternion(const std::array<float, 4>& q,
                                          const std::array<float, 4>& previous);

}  // namespace f2
