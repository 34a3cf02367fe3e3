#pragma once
/// The frame the renderer traces: the evaluated scene (anim) and the BVH
/// over its primitives, which the renderer keeps from frame to frame and
/// refits or rebuilds (Bvh::update).
#include "core/anim/evaluated_frame.h"
#include "core/geometry/bvh.h"

namespace f2 {

struct PreparedFrame : EvaluatedFrame {
    Bvh bvh;
};

}  // namespace f2
