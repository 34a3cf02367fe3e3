#include "core/anim/camera_motion.h"

#include <algorithm>
#include <cmath>

#include "core/anim/frame_builder.h"
#include "core/anim/track.h"

namespace f2 {

namespace {
constexpr double kDegreesPerRadian = 180.0 / kPi;
}  // namespace

Vec3 lookAtRotation(double toX, double toY, double toZ, double ry) {
    const double length = std::sqrt(toX * toX + toY * toY + toZ * toZ);
    const double fy = std::clamp(toY / length, -1.0, 1.0);  // rounding must not leave asin's domain
    const double rx = -std::asin(fy) * kDegreesPerRadian;
    if (toX != 0 || toZ != 0) ry = std::atan2(toX, toZ) * kDegreesPerRadian;
    return {float(rx), float(ry), 0.0f};
}

Vec3 lookAtPoint(const SceneDesc& scene, const LookAt& lookAt, double t) {
    if (!lookAt.target) return lookAt.point;
    const FrameRef ref = *lookAt.target;
    const Transform world = worldFromRef(scene, ref, t);
    if (ref.part < 0) return world.translation;  // an object's origin
    return partShapeCentre(scene.objects[ref.object], ref.part, world);
}

Transform cameraFrameAt(const SceneDesc& scene, double t) {
    const CameraDesc& camera = scene.camera;
    const Pose local = evaluateTrack(camera.track, t, camera.pose);
    Transform world = Transform::fromPose(local.position, local.rotation);
    if (camera.attachedTo) world = worldFromRef(scene, *camera.attachedTo, t) * world;
    if (!camera.lookAt) return world;

    // In double: the differences of two floats are exact, so "the point is the
    // eye" and "straight above or below" are exact tests.
    const Vec3 point = lookAtPoint(scene, *camera.lookAt, t);
    const Vec3 eye = world.translation;
    const double dx = double(point.x) - eye.x, dy = double(point.y) - eye.y, dz = double(point.z) - eye.z;
    if (dx == 0 && dy == 0 && dz == 0) return world;  // the keyed rotation
    // Coordinates beyond the float range (an attachment chain can add up past
    // it) give no direction: keep the rotation rather than make a NaN one.
    if (!std::isfinite(dx) || !std::isfinite(dy) || !std::isfinite(dz)) return world;
    // Straight up or down: an attached camera keeps the world rotation it would
    // have without /look_at; a free one keeps its keyed ry (SPEC 9.1, 9.2).
    if (dx == 0 && dz == 0 && camera.attachedTo) return world;
    world.linear = rotationFromEulerDegrees(lookAtRotation(dx, dy, dz, local.rotation.y));
    return world;
}

double cameraDistanceAt(const SceneDesc& scene, double t) {
    const Track& zoom = scene.camera.zoom;
    const double written = scene.camera.distance;
    if (zoom.keys.empty() && !zoom.drives) return written;
    // The smallest d a key may have is above 0; a curve (or a drive) that dips
    // below it stops at a thousandth of the smallest key (of `/camera`'s d
    // without keys).
    double smallest = zoom.keys.empty() ? written : double(zoom.keys.front().pose.position.x);
    for (const Key& k : zoom.keys) smallest = std::min(smallest, double(k.pose.position.x));
    const Pose rest{{float(written), 0, 0}, {}};
    return std::max(double(evaluateTrack(zoom, t, rest).position.x), smallest / 1000.0);
}

}  // namespace f2
