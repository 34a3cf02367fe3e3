#include "frame_range.h"

#include <charconv>
#include <numeric>

namespace f2::cli {

namespace {
template <typename T>
bool parseInt(std::string_view text, T& value) {
    const char* end = text.data() + text.size();
    auto result = std::from_chars(text.data(), end, value);
    return !text.empty() && result.ec == std::errc{} && result.ptr == end;
}

const std::string kFramesSyntax = "FIRST-LAST, FIRST or FIRST-, optionally :STEP";
}  // namespace

std::int64_t outputLastFrame(std::int64_t sceneLastFrame, int sceneFps, int outputFps) {
    // Exact in 64 bits (at most 10^7 * 1000); the division rounds down: the
    // last output frame is the last one within the animation.
    return sceneLastFrame * outputFps / sceneFps;
}

std::optional<FrameRange> parseFrameRange(const std::string& text, std::int64_t lastFrame, std::string& error) {
    std::string_view s = text;
    FrameRange range;
    const auto colon = s.find(':');
    if (colon != std::string_view::npos) {
        if (!parseInt(s.substr(colon + 1), range.step) || range.step < 1 || range.step > kMaxOutputFrame) {
            error = "--frames " + text + ": the step after ':' must be a whole number from 1 to " +
                    std::to_string(kMaxOutputFrame);
            return std::nullopt;
        }
        s = s.substr(0, colon);
    }
    const auto dash = s.find('-');
    const bool open = dash != std::string_view::npos && dash + 1 == s.size();
    const bool ok = dash == std::string_view::npos
                        ? parseInt(s, range.first) && (range.last = range.first, true)
                        : parseInt(s.substr(0, dash), range.first) &&
                              (open ? (range.last = lastFrame, true) : parseInt(s.substr(dash + 1), range.last));
    if (!ok || range.first < 0 || range.first > kMaxOutputFrame || (!open && range.last > kMaxOutputFrame)) {
        error = "--frames: expected " + kFramesSyntax + " (frame numbers 0.." + std::to_string(kMaxOutputFrame) +
                "), got '" + text + "'";
        return std::nullopt;
    }
    if (open && range.last > kMaxOutputFrame) {
        error = "--frames " + text + ": the animation ends at output frame " + std::to_string(range.last) +
                ", past the limit of " + std::to_string(kMaxOutputFrame) + "; give a last frame or a lower --fps";
        return std::nullopt;
    }
    if (range.last < range.first) {
        error = "--frames " + text + ": the last frame (" + std::to_string(range.last) +
                ") comes before the first";
        return std::nullopt;
    }
    return range;
}

std::string pastTheEndWarning(const FrameRange& range, std::int64_t lastFrame, int fps) {
    const std::int64_t from = range.first > lastFrame ? range.first : lastFrame + 1;
    const std::string frames = from == range.lastRendered()
                                   ? "frame " + std::to_string(from) + " is"
                                   : "frames " + std::to_string(from) + "-" + std::to_string(range.lastRendered()) +
                                         " are";
    return frames + " past the animation's last frame " + std::to_string(lastFrame) + " (at " +
           std::to_string(fps) + " fps): " + (from == range.lastRendered() ? "it shows" : "they show") +
           " its final pose";
}

std::int64_t Shard::countIn(const FrameRange& range) const {
    // Frame first + k*step (k = 0..count-1) is ours when it is index mod N.
    // Whether it is repeats in k with period N / gcd(step, N): count one
    // period, then the whole periods and the rest.
    const std::int64_t n = count;
    const std::int64_t period = n / std::gcd(range.step % n, n);
    const std::int64_t frames = range.count();
    auto ours = [&](std::int64_t k) { return contains(range.first + k * range.step); };
    std::int64_t perPeriod = 0, rest = 0;
    for (std::int64_t k = 0; k < period && k < frames; ++k) {
        if (!ours(k)) continue;
        ++perPeriod;
        if (k < frames % period) ++rest;
    }
    return frames / period * perPeriod + rest;
}

std::optional<Shard> parseShard(const std::string& text, std::string& error) {
    std::string_view s = text;
    auto slash = s.find('/');
    Shard shard;
    if (slash == std::string_view::npos || !parseInt(s.substr(0, slash), shard.index) ||
        !parseInt(s.substr(slash + 1), shard.count) || shard.count < 1 || shard.count > 100000 ||
        shard.index < 0 || shard.index >= shard.count) {
        error = "--shard: expected K/N with 0 <= K < N (worker K of N, counted from 0), got '" + text + "'";
        return std::nullopt;
    }
    return shard;
}

}  // namespace f2::cli
