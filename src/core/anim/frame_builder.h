#pragma once
/// Evaluates the animation of a scene at a time: key frames -> part frames ->
/// world-space primitives.
#include "core/anim/evaluated_frame.h"
#include "core/math/transform.h"
#include "core/util/thread_pool.h"

namespace f2 {

/// World transform of every part of a model placed at `worldFromRoot`, with the
/// parts' animation evaluated at `t` (indexed by PartId).
std::array<Transform, kPartCount> modelPartFrames(const SceneObject& object, const Transform& worldFromRoot,
                                                  double t);

/// World transform of an object's root (a primitive's own frame) at time t.
Transform objectFrame(const SceneObject& object, double t);

/// Fills `frame` (primitives, surfaces, lights) for time `t` in frames, on the
/// pool's threads when one is given. The BVH is the renderer's business
/// (FrameScene::bvh, updated from frame.primitives).
void evaluateFrame(const SceneDesc& scene, double t, EvaluatedFrame& frame, ThreadPool* pool = nullptr);

}  // namespace f2
