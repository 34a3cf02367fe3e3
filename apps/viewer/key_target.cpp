#include "key_target.h"

#include <algorithm>

#include "capture_pose.h"
#include "core/anim/camera_motion.h"
#include "core/anim/frame_builder.h"
#include "core/anim/light_evaluation.h"
#include "core/anim/track.h"
#include "core/scene/models.h"

namespace f2::viewer {

namespace {

/// The lightMotions index of the named light `name` that has a pose (not an `/amb_light`).
std::optional<std::size_t> posedLight(const SceneDesc& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.lightMotions.size(); ++i)
        if (!scene.lightMotions[i].ambient && scene.lightMotions[i].name == name) return i;
    return std::nullopt;
}

/// Where a named light's handles go in its own frame: its written position
/// (a point or spot light's), else the frame's origin (a directional light).
Vec3 lightHandle(const SceneDesc& scene, std::size_t motion) {
    for (const LocalLight& light : scene.localLights)
        if (light.motion == std::int32_t(motion)) return light.position;
    return {};
}

/// The world frame of `ref`, or the world itself when it rides on nothing.
Transform mountFrame(const SceneDesc& scene, const std::optional<FrameRef>& ref, double t) {
    return ref ? worldFromRef(scene, *ref, t) : Transform{};
}

/// targetTrack for a scene that may be changed (`Scene` is SceneDesc or const SceneDesc).
template <class Scene>
auto* trackIn(Scene& scene, const Selection& target) {
    using TrackPtr = decltype(&scene.camera.track);
    switch (target.kind) {
        case Selection::Kind::Camera:
            return &scene.camera.track;
        case Selection::Kind::Light: {
            const auto light = posedLight(scene, target.object);
            return light ? &scene.lightMotions[*light].track : TrackPtr{};
        }
        case Selection::Kind::Object:
            break;
    }
    const auto object = findObject(scene, target);
    if (!object) return TrackPtr{};
    auto& o = scene.objects[*object];
    return target.part ? &o.partTracks[std::size_t(*target.part)] : &o.track;
}

}  // namespace

const Track* targetTrack(const SceneDesc& scene, const Selection& target) { return trackIn(scene, target); }

std::optional<GizmoFrame> targetKeyFrame(const SceneDesc& scene, const Selection& target, int frame) {
    GizmoFrame key;
    if (target.kind == Selection::Kind::Camera) {
        key.pose = cameraKeyPose(scene, frame, std::nullopt);
        key.parent = mountFrame(scene, scene.camera.attachedTo, frame);
        return key;
    }
    if (target.kind == Selection::Kind::Light) {
        const auto light = posedLight(scene, target.object);
        if (!light) return std::nullopt;
        const LightMotion& motion = scene.lightMotions[*light];
        key.pose = evaluateTrack(motion.track, frame, Pose{});
        key.parent = mountFrame(scene, motion.attachedTo, frame);
        key.handle = lightHandle(scene, *light);
        return key;
    }
    const auto object = findObject(scene, target);
    if (!object) return std::nullopt;
    const SceneObject& o = scene.objects[*object];
    key.pose = selectionKeyPose(scene, *object, target.part, frame);
    if (target.part) {
        // partFrame (models.h): parent · translate(pivot + offset) · rest · rotate.
        const ModelPart& p = o.model->parts[std::size_t(*target.part)];
        key.parent =
            worldFromRef(scene, FrameRef{std::uint32_t(*object), p.parent}, frame).translated(p.pivot);
        if (p.rest) key.rest = *p.rest;
    } else {
        key.parent = mountFrame(scene, mountAt(o, frame), frame);
    }
    return key;
}

std::shared_ptr<const SceneDesc> sceneWithKey(const SceneDesc& scene, const Selection& target, int frame,
                                              const Pose& pose) {
    auto copy = std::make_shared<SceneDesc>(scene);  // its animation is compiled anew
    Track* track = trackIn(*copy, target);
    if (!track) return nullptr;
    std::vector<Key>& keys = track->keys;
    const auto at = std::lower_bound(keys.begin(), keys.end(), double(frame),
                                     [](const Key& key, double time) { return key.time < time; });
    if (at != keys.end() && at->time == double(frame))
        at->pose = pose;
    else
        keys.insert(at, Key{double(frame), pose});
    return copy;
}

std::optional<Vec3> targetPosition(const SceneDesc& scene, const Selection& target, double t) {
    if (target.kind == Selection::Kind::Camera) return cameraFrameAt(scene, t).translation;
    if (target.kind == Selection::Kind::Light) {
        const auto light = posedLight(scene, target.object);
        if (!light) return std::nullopt;
        return lightFrameAt(scene, scene.lightMotions[*light], t).applyToPoint(lightHandle(scene, *light));
    }
    const auto object = findObject(scene, target);
    if (!object) return std::nullopt;
    const Transform world =
        worldFromRef(scene, FrameRef{std::uint32_t(*object), target.part.value_or(-1)}, t);
    return target.part ? partShapeCentre(scene.objects[*object], *target.part, world) : world.translation;
}

std::vector<TargetMarker> targetMarkers(const SceneDesc& scene, double t) {
    std::vector<TargetMarker> markers;
    for (const LightMotion& light : scene.lightMotions) {
        if (light.ambient) continue;
        Selection target{light.name, std::nullopt, {}};
        target.kind = Selection::Kind::Light;
        markers.push_back({target, *targetPosition(scene, target, t)});
    }
    Selection camera{"camera", std::nullopt, {}};
    camera.kind = Selection::Kind::Camera;
    markers.push_back({camera, cameraFrameAt(scene, t).translation});
    return markers;
}

}  // namespace f2::viewer
