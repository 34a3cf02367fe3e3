#pragma once
/// A frame's preparation for tracing: the scene evaluated at a time and its
/// BVH updated, the evaluation written straight into the tree's leaf order
/// whenever the last tree is refitted.
#include "core/render/frame_scene.h"
#include "core/scene/scene_desc.h"
#include "core/util/thread_pool.h"

namespace f2 {

/// How long prepareFrame() took, by part (ms, wall time).
struct PreparationTimes {
    /// Evaluation on its own: all of it when the tree is built, else only what
    /// comes before the objects (lights, key segments).
    double evaluateMs = 0;
    /// Bvh::update; when the last tree is refitted, the objects' evaluation too,
    /// which writes into its leaves in place of the refit's copy.
    double buildMs = 0;
};

/// evaluateFrame(scene, t, frame, pool) then frame.bvh.update(frame.primitives,
/// pool), with the same results bit for bit (primitives, tree, leaf order):
/// when the frame is refilled by the same animation program and the last tree
/// is refitted, each primitive is evaluated into both the frame and its slot of
/// the leaf order, instead of into the frame and then copied (a pass over 64
/// bytes a primitive that large scenes pay from memory).
PreparationTimes prepareFrame(const SceneDesc& scene, double t, FrameScene& frame, ThreadPool* pool);

}  // namespace f2
