#pragma once
/// Which object or part a pixel shows: the viewer's click selection. It casts
/// the primary ray of the reference path (Camera::rayThrough, the same start
/// and BVH query as traceRay), so it names exactly what the renderer drew.
#include <cstddef>
#include <optional>

#include "core/render/camera.h"
#include "core/render/prepared_frame.h"
#include "core/scene/scene_desc.h"

namespace f2 {

/// A scene-level identity and where the ray met it.
struct PickHit {
    std::size_t object = 0;   ///< index into SceneDesc::objects
    std::optional<int> part;  ///< the part of a model instance (eyes belong to the head)
    int shape = 0;            ///< the shape among the object's primitives (0 for a primitive)
    Vec3 point;               ///< world position of the hit
    float distance = 0;       ///< along the ray, from the eye
};

/// What image point (px, py) (pixel coordinates as Camera::rayThrough; the
/// centre of pixel (i, j) is (i + 0.5, j + 0.5)) shows in `frame`, which is
/// `scene` evaluated at some time with its BVH built. Nothing for the background.
std::optional<PickHit> pickPoint(const SceneDesc& scene, const PreparedFrame& frame, const Camera& camera,
                                 float px, float py);

/// What pixel (x, y) of `camera`'s image shows at time `t` (evaluates the frame).
std::optional<PickHit> pickPixel(const SceneDesc& scene, double t, const Camera& camera, int x, int y);

/// World bounds of object `object` of `scene` in `frame` (evaluated from it),
/// or of one part of a model instance.
Bounds selectionBounds(const SceneDesc& scene, const EvaluatedFrame& frame, std::size_t object,
                       std::optional<int> part);

}  // namespace f2
