#pragma once
/// Evaluates the animation of a scene at a time: key frames -> part frames ->
/// world-space primitives.
#include <memory>
#include <span>

#include "core/anim/evaluated_frame.h"
#include "core/math/transform.h"
#include "core/util/thread_pool.h"

namespace f2 {

/// World transform of every part of a model placed at `worldFromRoot`, with the
/// parts' animation evaluated at `t` (indexed by PartId).
std::array<Transform, kPartCount> modelPartFrames(const SceneObject& object, const Transform& worldFromRoot,
                                                  double t);

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

/// World root frame of object i: `roots` (from attachedRootFrames) when it is
/// attached, else its own pose.
inline Transform worldFromRoot(const SceneDesc& scene, std::size_t i, double t,
                               const std::vector<Transform>& roots) {
    const SceneObject& object = scene.objects[i];
    return object.attachedTo ? roots[i] : objectFrame(object, t);
}

/// World position of the centre of a part's shape (its main shape: a robot's
/// head box, not its eyes) whose part frame is `worldFromPart`.
Vec3 partShapeCentre(ObjectKind kind, int part, const Transform& worldFromPart);

/// Fills `frame` (primitives, surfaces, lights) for time `t` in frames, on the
/// pool's threads when one is given, from the scene's compiled animation
/// (animation_program.h; compiled by the first call for a scene). Gives the
/// bits that the object-by-object functions above give. The BVH is the
/// renderer's business (FrameScene::bvh, updated from frame.primitives).
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
    void finish(EvaluatedFrame& frame) && { frame.filledBy = std::move(program); }
};

}  // namespace f2
