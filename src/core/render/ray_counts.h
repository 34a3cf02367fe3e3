#pragma once
/// Rays a frame cast, for the timings and the benchmark's rays per second.
#include <cstdint>

namespace f2 {

/// Rays traced, counted as they are cast.
struct RayCounts {
    std::uint64_t primary = 0, shadow = 0;
    std::uint64_t reflected = 0;  ///< mirror rays (docs/rendering.md)
    std::uint64_t total() const { return primary + shadow + reflected; }
};

}  // namespace f2
