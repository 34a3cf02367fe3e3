#pragma once
/// What the handles drag, for each kind of target (an object, a part, a named
/// light, the camera): its key at a frame and the frame that key is read in,
/// the scene with that key changed (the picture of a drag), where it is over
/// time (its motion path), and the lights and camera to click on. Pure
/// functions of the parsed scene, unit-tested without a window.
#include <memory>
#include <optional>
#include <vector>

#include "core/scene/scene_desc.h"
#include "gizmo.h"
#include "selection.h"

namespace f2::viewer {

/// The track of `target`'s pose keys in `scene`; null when the scene has no such target.
const Track* targetTrack(const SceneDesc& scene, const Selection& target);

/// `target`'s key at `frame` and where it is read (gizmo.h): an object's own
/// pose in the frame it rides on (the world's when it rides on nothing); a
/// part's offset and rotation in its parent's frame at its pivot, after its
/// rest rotation; a named light's pose, its handles at its written position
/// (a directional light's at its frame's origin); the camera's key pose (what
/// its keys give before `/look_at`). Nothing when the scene has no such target.
std::optional<GizmoFrame> targetKeyFrame(const SceneDesc& scene, const Selection& target, int frame);

/// A copy of `scene` whose `target` has a key at `frame` with `pose`: its key
/// there replaced (keeping its mode), else one added in time order. What the
/// text says once that key is written, without parsing it again: the picture
/// of a drag in progress. Null when the scene has no such target.
std::shared_ptr<const SceneDesc> sceneWithKey(const SceneDesc& scene, const Selection& target, int frame,
                                              const Pose& pose);

/// Where `target` is at time `t`, for its motion path: an object's origin, a
/// part's shape's centre, a light's position, the camera's eye.
std::optional<Vec3> targetPosition(const SceneDesc& scene, const Selection& target, double t);

/// The targets that have no surface to click: every named light with a pose
/// and the camera, where they are at time `t`.
struct TargetMarker {
    Selection target;
    Vec3 at;
};
std::vector<TargetMarker> targetMarkers(const SceneDesc& scene, double t);

}  // namespace f2::viewer
