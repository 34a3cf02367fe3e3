#pragma once
/// A frame's preparation for tracing: the scene evaluated at a time and its
/// BVH updated, the evaluation written straight into the tree's leaf order
/// whenever the last tree is refitted.
#include <cstddef>

#include "core/render/prepared_frame.h"
#include "core/scene/scene_desc.h"
#include "core/util/thread_pool.h"

namespace f2 {

/// How long prepareFrame() took, by part (ms, wall time).
struct PreparationTimes {
    /// Evaluation on its own: all of it, unless it was written into the
    /// leaves; then only what comes before the objects (lights, key segments).
    double evaluateMs = 0;
    /// Bvh::update; when the evaluation was written into the leaves, the
    /// objects' evaluation too (it takes the place of the refit's copy).
    double buildMs = 0;
};

/// Frames of this many primitives or more (4 MiB a copy, more than a core's
/// cache) are evaluated straight into the leaves by default; smaller ones fit
/// in cache, where writing both orders at once measured no faster than the copy.
inline constexpr std::size_t kIntoLeavesFrom = std::size_t{1} << 16;

/// evaluateFrame(scene, t, frame, pool) then frame.bvh.update(frame.primitives,
/// pool), with the same results bit for bit (primitives, tree, leaf order).
/// When the frame is refilled by the same animation program, the last tree is
/// refitted and the frame has `intoLeavesFrom` primitives or more, each
/// primitive is evaluated into both the frame and its slot of the leaf order,
/// around the caches, instead of into the frame and then copied into leaf
/// order (a pass over 64 bytes a primitive that large frames pay from memory).
PreparationTimes prepareFrame(const SceneDesc& scene, double t, PreparedFrame& frame, ThreadPool* pool,
                              std::size_t intoLeavesFrom = kIntoLeavesFrom);

}  // namespace f2
