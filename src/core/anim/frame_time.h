#pragma once
/// Time on an animation's timeline. Time is counted in the scene's frames and
/// may be fractional (SPEC 6); these are the one rule for turning a time into a
/// frame number and an output frame into a time, used by the command line, the
/// viewer and the animation output alike.
#include <cassert>
#include <cmath>
#include <cstdint>

namespace f2 {

/// The whole frame that time `t` (finite) falls in: floor(t), except that a
/// time a rounding error short of a whole number (as i·a/b computed in floating
/// point can be) counts as that number.
inline std::int64_t frameAt(double t) {
    assert(std::isfinite(t));
    return std::int64_t(std::floor(t + 1e-9 + std::fabs(t) * 1e-12));
}

/// Scene time shown by output frame `i` when the scene runs at `sceneFps` and
/// the output at `outputFps`: the animation keeps its duration at any output rate.
inline double sceneTimeOfOutputFrame(std::int64_t i, int sceneFps, int outputFps) {
    return double(i) * sceneFps / outputFps;
}

/// The output frame that shows scene time `t`: the inverse of sceneTimeOfOutputFrame.
inline std::int64_t outputFrameAt(double t, int sceneFps, int outputFps) {
    return frameAt(t * outputFps / sceneFps);
}

}  // namespace f2
