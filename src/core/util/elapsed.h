#pragma once
/// Wall time of the parts of a frame, as FrameTimings reports them.
#include <chrono>

namespace f2 {

using Clock = std::chrono::steady_clock;

/// Milliseconds from `start` to now.
inline double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace f2
