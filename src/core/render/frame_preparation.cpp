#include "core/render/frame_preparation.h"

#include <chrono>

#include "core/anim/frame_builder.h"
#include "core/util/elapsed.h"

namespace f2 {

PreparationTimes prepareFrame(const SceneDesc& scene, double t, PreparedFrame& frame, ThreadPool* pool,
                              std::size_t intoLeavesFrom) {
    PreparationTimes times;
    auto start = Clock::now();
    FrameEvaluation evaluation = FrameEvaluation::begin(scene, t, frame);
    // A frame not refilled needs its surfaces written, object by object.
    if (!evaluation.refill || !frame.bvh.refits(frame.primitives.size()) ||
        frame.primitives.size() < intoLeavesFrom) {
        evaluation.evaluateObjects(frame, pool);
        std::move(evaluation).finish(frame);
        times.evaluateMs = millisecondsSince(start);
        start = Clock::now();
        frame.bvh.update(frame.primitives, pool);
        frame.bvh.setRayMask(frame.rayMask);
        times.buildMs = millisecondsSince(start);
        return times;
    }
    times.evaluateMs = millisecondsSince(start);
    start = Clock::now();
    frame.bvh.update(
        frame.primitives,
        [&](std::span<const std::uint32_t> leafOf, std::span<Primitive> leaves) {
            evaluation.evaluateObjectsIntoLeaves(frame, leafOf, leaves, pool);
        },
        pool);
    std::move(evaluation).finish(frame);
    frame.bvh.setRayMask(frame.rayMask);
    times.buildMs = millisecondsSince(start);
    return times;
}

}  // namespace f2
