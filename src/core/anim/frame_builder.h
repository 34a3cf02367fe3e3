#pragma once
/// Evaluates the animation of a scene at a time: key frames -> part frames ->
/// world-space primitives.
#include <algorithm>
#include <memory>
#include <span>

#include "core/anim/evaluated_frame.h"
#include "core/anim/track.h"
#include "core/geometry/ray_mask.h"
#include "core/math/transform.h"
#include "core/scene/models.h"
#include "core/util/thread_pool.h"

namespace f2 {

/// World transform of every part of a model placed at `worldFromRoot`, with the
/// parts' animation evaluated at `t` (in the model's order of parts).
std::vector<Transform> modelPartFrames(const SceneObject& object, const Transform& worldFromRoot, double t);

/// The world transform of one part, `part`, of a model placed at
/// `worldFromRoot`: modelPartFrames(…)[part], bit for bit, without
/// allocating (an attachment to a part is evaluated every frame).
Transform modelPartFrame(const SceneObject& object, int part, const Transform& worldFromRoot, double t);

/// World transform of shape k of a model whose part frames are `worldFromPart`.
inline Transform modelShapeFrame(const SceneObject& object, std::size_t k,
                                 const std::vector<Transform>& worldFromPart) {
    const ModelShape& shape = object.model->shapes[k];
    return shapeFrame(worldFromPart[std::size_t(shape.part)], shape);
}

/// An object's root frame (a primitive's own frame) at time t from its own
/// pose alone: its world frame unless it is attached (SPEC 9.2).
Transform objectFrame(const SceneObject& object, double t);

/// World frame of `ref` at time t (SPEC 9.2): an object's root frame, or a
/// part's pivot frame, through every attachment above it. O(depth of the
/// attachment chain), no allocation.
Transform worldFromRef(const SceneDesc& scene, FrameRef ref, double t);

/// World root frames of the attached objects at time t into `roots` (indexed
/// by object; other entries untouched), parents first (SceneDesc::attachOrder).
/// Keeps the vector's capacity: no allocation in steady state.
void attachedRootFrames(const SceneDesc& scene, double t, std::vector<Transform>& roots);

/// World root frame of object i: `roots` (from attachedRootFrames) when it may
/// ride on something (SPEC 9.2, 10.7), else its own pose.
inline Transform worldFromRoot(const SceneDesc& scene, std::size_t i, double t,
                               const std::vector<Transform>& roots) {
    const SceneObject& object = scene.objects[i];
    return object.mayRide() ? roots[i] : objectFrame(object, t);
}

/// World position of the centre of a part's main shape (its first: a robot's
/// head box, not its eyes) whose part frame is `worldFromPart`; the pivot
/// when the part has no shape.
Vec3 partShapeCentre(const SceneObject& object, int part, const Transform& worldFromPart);

/// Fills `frame` (primitives, surfaces, lights) for time `t` in frames, on the
/// pool's threads when one is given, from the scene's compiled animation
/// (animation_program.h; compiled by the first call for a scene). Gives the
/// bits that the object-by-object functions above give. The BVH is the
/// renderer's business (PreparedFrame::bvh, updated from frame.primitives).
/// `t` must be a finite number (asserted; the front ends refuse others).
void evaluateFrame(const SceneDesc& scene, double t, EvaluatedFrame& frame, ThreadPool* pool = nullptr);

/// evaluateFrame in two halves, for a caller that writes the objects' primitives
/// itself (render/frame_preparation.h): begin() does everything but the
/// objects (lights, attached roots, where t falls among the keys, the arrays
/// sized); then every object is evaluated, by evaluateObjects() or by the
/// caller with `program` (AnimationProgram::evaluatePrimitives); then finish().
struct FrameEvaluation {
    std::shared_ptr<const AnimationProgram> program;
    /// The frame already holds this program's surfaces and still objects.
    bool refill = false;

    static FrameEvaluation begin(const SceneDesc& scene, double t, EvaluatedFrame& frame);
    /// Every object's primitives (and surfaces), in scene order, on the pool's threads if given.
    void evaluateObjects(EvaluatedFrame& frame, ThreadPool* pool) const;
    /// The same for a refilled frame, also writing primitive i into
    /// leaves[leafOf[i]] (AnimationProgram::evaluateObjectsIntoLeaves).
    void evaluateObjectsIntoLeaves(EvaluatedFrame& frame, std::span<const std::uint32_t> leafOf,
                                   std::span<Primitive> leaves, ThreadPool* pool) const;
    /// The colour keys (applyColourTracks), the ray mask (`/no_shadow`,
    /// markHiddenShapes), and the frame is whole.
    void finish(EvaluatedFrame& frame) &&;

    const SceneDesc* scene = nullptr;
    double t = 0;
};

/// Sets the colours of the shapes that `colour` keys reach (SPEC 10.3) at
/// time t, over the surfaces evaluated from `/paint`.
void applyColourTracks(const SceneDesc& scene, double t, EvaluatedFrame& frame);

/// Marks ray_mask::kHidden in frame.rayMask (made the frame's own, over the
/// program's `/no_shadow` flags) for the shapes hidden at time t (SPEC 10.7).
void markHiddenShapes(const SceneDesc& scene, double t, EvaluatedFrame& frame);

/// Whether a `visible` track shows its target at time t (SPEC 10.7): its
/// keys are steps of 0 and 1; before the first key the first holds.
inline bool visibleAt(const Track& track, double t) {
    return track.keys.empty() || evaluateTrack(track, t, Pose{}).position.x >= 0.5f;
}

/// Calls visit(shape, model shape or nullptr) for each shape of `target` (an
/// object, a model's part, or the model's shape `shape`): a primitive is its
/// own shape 0; a model's shapes are indexed among its primitives.
template <class Visit>
void forEachShapeOf(const SceneDesc& scene, FrameRef target, int shape, Visit&& visit) {
    const SceneObject& object = scene.objects[target.object];
    if (!object.model) {
        visit(std::size_t(0), static_cast<const ModelShape*>(nullptr));
        return;
    }
    const std::vector<ModelShape>& shapes = object.model->shapes;
    if (shape >= 0) {
        visit(std::size_t(shape), &shapes[std::size_t(shape)]);
        return;
    }
    for (std::size_t k = 0; k < shapes.size(); ++k) {
        if (target.part < 0 || shapes[k].part == target.part) visit(k, &shapes[k]);
    }
}

/// Calls visit(object, shape) for every shape hidden at time t: a shape is
/// seen while its object's, its part's and its own `visible` tracks (where
/// they have one) all show it (SPEC 10.7). A shape may be visited twice.
template <class Visit>
void forEachHiddenShape(const SceneDesc& scene, double t, Visit&& visit) {
    for (const TargetTrack& v : scene.visibilityTracks) {
        if (visibleAt(v.track, t)) continue;
        forEachShapeOf(scene, v.target, v.shape, [&](std::size_t shape, const ModelShape*) {
            visit(std::size_t(v.target.object), shape);
        });
    }
}

/// Calls visit(object, shape, rgb) for every shape a `colour` track reaches at
/// time t (shape: its index among the object's primitives; rgb: 0..255,
/// unrounded), least specific target first, so the last call for a shape
/// is its colour. A shape painted in its model is reached only by its own
/// track (SPEC 10.3). A track with drives and no keys (SPEC 10.7) keeps each
/// shape's `/paint` in the channels it does not drive.
template <class Visit>
void forEachKeyedColour(const SceneDesc& scene, double t, Visit&& visit) {
    // An easing that overshoots, or a drive, stops at the ends of the scale.
    const auto clamped = [](Vec3 v) {
        return Vec3{std::clamp(v.x, 0.0f, 255.0f), std::clamp(v.y, 0.0f, 255.0f),
                    std::clamp(v.z, 0.0f, 255.0f)};
    };
    for (const TargetTrack& c : scene.colourTracks) {
        const bool keyed = !c.track.keys.empty();
        if (!keyed && !c.track.drives) continue;
        const Vec3 rgb = keyed ? clamped(evaluateTrack(c.track, t, Pose{}).position) : Vec3{};
        const SceneObject& object = scene.objects[c.target.object];
        forEachShapeOf(scene, c.target, c.shape, [&](std::size_t shape, const ModelShape* inModel) {
            if (inModel && inModel->ownColor && c.shape < 0) return;
            if (keyed) return visit(std::size_t(c.target.object), shape, rgb);
            const Color8 paint = object.appearance[shape].color;
            const Pose rest{{float(paint.r), float(paint.g), float(paint.b)}, {}};
            visit(std::size_t(c.target.object), shape, clamped(evaluateTrack(c.track, t, rest).position));
        });
    }
}

}  // namespace f2
