#pragma once
/// The poses *Capture* writes into `/key` lines: what the selection or the
/// camera is at a frame, as the key's six numbers mean it (SPEC 6, 9.1, 9.2).
/// Pure functions of the scene, so they are unit-tested without a window.
#include <optional>

#include "core/render/pick.h"
#include "core/scene/scene_desc.h"

namespace f2::viewer {

/// The key of object `object` (or of its `part`) that holds it where its
/// animation has it at `frame`: an object's own pose (in the frame it rides
/// on, if attached), a part's offset and rotation about its pivot.
Pose selectionKeyPose(const SceneDesc& scene, std::size_t object, std::optional<int> part, int frame);

/// The camera key for `frame`. Without `view`, the pose the camera's keys
/// give there (its `/camera` pose without keys), so keying changes nothing on
/// screen. With `view` (a world-space eye and rotation: the look-around), the
/// key that puts the camera there: read in the frame the camera rides on when
/// it is attached (SPEC 9.2). A `/look_at` still replaces the rotation.
Pose cameraKeyPose(const SceneDesc& scene, int frame, const std::optional<Pose>& view);

}  // namespace f2::viewer
