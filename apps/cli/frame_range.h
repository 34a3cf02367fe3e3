#pragma once
/// Which frames `f2 render` renders: a range (`--frames 0-239`) and a shard of
/// it (`--shard K/N`) for render farms.
#include <optional>
#include <string>

namespace f2::cli {

/// Inclusive range of output frame numbers.
struct FrameRange {
    int first = 0, last = 0;
    int count() const { return last - first + 1; }
};

/// "A-B", "A" (one frame) or "A-" (A to `lastFrame`); 0 <= A <= B <= 10^7.
std::optional<FrameRange> parseFrameRange(const std::string& text, int lastFrame, std::string& error);

/// Worker K of N takes every frame whose number is K modulo N (round-robin,
/// not contiguous blocks): frame cost changes along an animation, so
/// interleaving gives every worker the same mix and they finish together, and
/// a frame's worker does not depend on --frames.
struct Shard {
    int index = 0, count = 1;
    bool contains(int frame) const { return frame % count == index; }
    /// How many frames of `range` this shard renders.
    int countIn(const FrameRange& range) const;
};

/// "K/N" with 0 <= K < N <= 100000.
std::optional<Shard> parseShard(const std::string& text, std::string& error);

}  // namespace f2::cli
