#include "frame_range.h"

#include <charconv>

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

std::optional<FrameRange> parseFrameRange(const std::string& text, std::int64_t lastFrame,
                                          std::string& error) {
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
    const bool ok =
        dash == std::string_view::npos
            ? parseInt(s, range.first) && (range.last = range.first, true)
            : parseInt(s.substr(0, dash), range.first) &&
                  (open ? (range.last = lastFrame, true) : parseInt(s.substr(dash + 1), range.last));
    if (!ok || range.first < 0 || range.first > kMaxOutputFrame || (!open && range.last > kMaxOutputFrame)) {
        error = "--frames: expected " + kFramesSyntax + " (frame numbers 0.." +
                std::to_string(kMaxOutputFrame) + "), got '" + text + "'";
        return std::nullopt;
    }
    if (open && range.last > kMaxOutputFrame) {
        error = "--frames " + text + ": the animation ends at output frame " + std::to_string(range.last) +
                ", past the limit of " + std::to_string(kMaxOutputFrame) +
                "; give a last frame or a lower --fps";
        return std::nullopt;
    }
    if (range.last < range.first) {
        error = "--frames " + text + ": the last frame (" + std::to_string(range.last) +
                ") comes before the first";
        return std::nullopt;
    }
    return range;
}

std::string pastTheEndWarning(const AnimationRange& range, std::int64_t lastFrame) {
    const std::int64_t from = range.first > lastFrame ? range.first : lastFrame + 1;
    const std::string frames =
        from == range.lastRendered()
            ? "frame " + std::to_string(from) + " is"
            : "frames " + std::to_string(from) + "-" + std::to_string(range.lastRendered()) + " are";
    return frames + " past the animation's last frame " + std::to_string(lastFrame) + " (at " +
           std::to_string(range.outputFps) +
           " fps): " + (from == range.lastRendered() ? "it shows" : "they show") + " its final pose";
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
