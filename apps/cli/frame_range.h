#pragma once
/// Which frames `f2 render` renders: a range with an optional step
/// (`--frames 0-239:4`) and a shard of it (`--shard K/N`) for render farms.
/// Frame numbers and counts are 64-bit and range-checked: an animation's
/// length at a high output --fps is computed, never overflowed.
#include <cstdint>
#include <optional>
#include <string>

#include "core/scene/limits.h"
#include "io/render_animation.h"

namespace f2::cli {

/// The largest output frame number (`--frames`, and the last frame of the
/// default range at the output --fps): SPEC 7's limit on key frame numbers.
inline constexpr std::int64_t kMaxOutputFrame = kMaxKeyFrame;

/// Output frames first, first + step, ... up to last (inclusive).
struct FrameRange {
    std::int64_t first = 0, last = 0, step = 1;
    std::int64_t count() const { return (last - first) / step + 1; }
};

/// "A-B", "A" (one frame) or "A-" (A to `lastFrame`), each optionally followed
/// by ":S" (every S-th frame from A); 0 <= A <= B <= kMaxOutputFrame.
std::optional<FrameRange> parseFrameRange(const std::string& text, std::int64_t lastFrame,
                                          std::string& error);

/// "frames 241-400 are past the animation's last frame 240 (at 24 fps): they
/// show its final pose", for a range that ends after `lastFrame`.
std::string pastTheEndWarning(const AnimationRange& range, std::int64_t lastFrame);

/// Worker K of N takes every frame whose number is K modulo N (round-robin,
/// not contiguous blocks): frame cost changes along an animation, so
/// interleaving gives every worker the same mix and they finish together, and
/// a frame's worker does not depend on --frames.
struct Shard {
    int index = 0, count = 1;
};

/// "K/N" with 0 <= K < N <= 100000.
std::optional<Shard> parseShard(const std::string& text, std::string& error);

}  // namespace f2::cli
