#include "frame_range.h"

#include <charconv>

namespace f2::cli {

namespace {
constexpr int kMaxFrame = 10'000'000;  // SPEC 7's limit on key frame numbers

bool parseInt(std::string_view text, int& value) {
    const char* end = text.data() + text.size();
    auto result = std::from_chars(text.data(), end, value);
    return !text.empty() && result.ec == std::errc{} && result.ptr == end;
}
}  // namespace

std::optional<FrameRange> parseFrameRange(const std::string& text, int lastFrame, std::string& error) {
    std::string_view s = text;
    FrameRange range;
    auto dash = s.find('-');
    bool ok = dash == std::string_view::npos
                  ? parseInt(s, range.first) && (range.last = range.first, true)
                  : parseInt(s.substr(0, dash), range.first) &&
                        (dash + 1 == s.size() ? (range.last = lastFrame, true)
                                              : parseInt(s.substr(dash + 1), range.last));
    if (!ok || range.first < 0 || range.last > kMaxFrame) {
        error = "--frames: expected FIRST-LAST, FIRST or FIRST- (frame numbers 0.." +
                std::to_string(kMaxFrame) + "), got '" + text + "'";
        return std::nullopt;
    }
    if (range.last < range.first) {
        error = "--frames " + text + ": the last frame comes before the first";
        return std::nullopt;
    }
    return range;
}

int Shard::countIn(const FrameRange& range) const {
    // Frames f in [first, last] with f = index (mod count).
    auto upTo = [this](int n) { return n < index ? 0 : (n - index) / count + 1; };  // in [0, n]
    return upTo(range.last) - (range.first > 0 ? upTo(range.first - 1) : 0);
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
