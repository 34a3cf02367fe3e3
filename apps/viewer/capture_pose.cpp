#include "capture_pose.h"

#include "core/anim/frame_builder.h"
#include "core/anim/track.h"
#include "core/math/transform.h"
#include "core/scene/models.h"

namespace f2::viewer {

Pose selectionKeyPose(const SceneDesc& scene, std::size_t object, std::optional<int> part, int frame) {
    const SceneObject& target = scene.objects[object];
    return part ? evaluateTrack(target.partTracks[std::size_t(*part)], frame, Pose{})
                : evaluateTrack(target.track, frame, target.rest);
}

GizmoFrame selectionKeyFrame(const SceneDesc& scene, std::size_t object, std::optional<int> part, int frame) {
    const SceneObject& target = scene.objects[object];
    GizmoFrame key;
    key.pose = selectionKeyPose(scene, object, part, frame);
    if (part) {
        // partFrame (models.h): parent · translate(pivot + offset) · rest · rotate.
        const ModelPart& p = target.model->parts[std::size_t(*part)];
        const FrameRef parent{std::uint32_t(object), p.parent};
        key.parent = worldFromRef(scene, parent, frame).translated(p.pivot);
        if (p.rest) key.rest = *p.rest;
    } else if (const auto mount = mountAt(target, frame)) {
        key.parent = worldFromRef(scene, *mount, frame);
    }
    return key;
}

std::shared_ptr<const SceneDesc> sceneWithKey(const SceneDesc& scene, std::size_t object,
                                              std::optional<int> part, int frame, const Pose& pose) {
    auto copy = std::make_shared<SceneDesc>(scene);  // its animation is compiled anew
    SceneObject& target = copy->objects[object];
    std::vector<Key>& keys = (part ? target.partTracks[std::size_t(*part)] : target.track).keys;
    const auto at = std::lower_bound(keys.begin(), keys.end(), double(frame),
                                     [](const Key& key, double time) { return key.time < time; });
    if (at != keys.end() && at->time == double(frame))
        at->pose = pose;
    else
        keys.insert(at, Key{double(frame), pose});
    return copy;
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
