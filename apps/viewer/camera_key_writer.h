#pragma once
/// What *Capture › Key Camera Here* writes. The camera's first key also decides
/// every frame before it (before the first key, the first key holds), so a
/// first key away from frame 0 would move the whole shot's start: it comes with
/// `/key 0 camera` at the pose the shot had there (the `/camera` pose), in the
/// same undo step. A pure function of the text and the scene, like text_capture.h.
#include <QString>
#include <vector>

#include "core/scene/scene_desc.h"
#include "text_capture.h"

namespace f2::viewer {

/// The edits of one *Key Camera Here*, applied in order as one undo step.
struct CameraKeyWrite {
    std::vector<TextEdit> edits;
    /// The status bar's note when a frame-0 key came with it, else empty.
    QString note;
};

/// The camera key at `frame` with `pose` (capture_pose.h's cameraKeyPose) for
/// `text`, whose last parse is `scene`: replaces the camera's key at that
/// frame, else goes after its last `/key`, else after the `/camera` line. When
/// the camera has no key yet and `frame` is not 0, `/key 0 camera` with the
/// `/camera` pose goes first, so frames before `frame` still show the shot as it was.
CameraKeyWrite cameraKeyWrite(const QString& text, const SceneDesc& scene, int frame, const Pose& pose);

}  // namespace f2::viewer
