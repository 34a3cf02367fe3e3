#include "capture_pose.h"

#include "core/anim/frame_builder.h"
#include "core/anim/track.h"
#include "core/math/transform.h"

namespace f2::viewer {

Pose selectionKeyPose(const SceneDesc& scene, std::size_t object, std::optional<int> part, int frame) {
    const SceneObject& target = scene.objects[object];
    return part ? evaluateTrack(target.partTracks[std::size_t(*part)], frame, Pose{})
                : evaluateTrack(target.track, frame, target.rest);
}

Pose cameraKeyPose(const SceneDesc& scene, int frame, const std::optional<Pose>& view) {
    const CameraDesc& camera = scene.camera;
    if (!view) return evaluateTrack(camera.track, frame, camera.pose);
    if (!camera.attachedTo) return *view;
    // local = parentFromWorld * worldFromView
    const Transform local = worldFromRef(scene, *camera.attachedTo, frame).inverseRigid() *
                            Transform::fromPose(view->position, view->rotation);
    return {local.translation, eulerDegreesFromRotation(local.linear)};
}

}  // namespace f2::viewer
