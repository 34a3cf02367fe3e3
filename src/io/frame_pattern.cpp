#include "io/frame_pattern.h"

#include <cctype>

namespace f2 {

std::string FramePattern::format(std::int64_t frame) const {
    std::string digits = std::to_string(frame);
    if (int(digits.size()) < width) digits.insert(0, std::size_t(width) - digits.size(), zeroPad ? '0' : ' ');
    return prefix + digits + suffix;
}

bool looksLikeFramePattern(const std::string& path) {
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i] != '%') continue;
        if (i + 1 < path.size() && path[i + 1] == '%') {
            ++i;
            continue;
        }
        return true;
    }
    return false;
}

std::optional<FramePattern> parseFramePattern(const std::string& path, std::string& error) {
    FramePattern pattern;
    std::string* text = &pattern.prefix;
    bool found = false;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i] != '%') {
            *text += path[i];
            continue;
        }
        if (i + 1 < path.size() && path[i + 1] == '%') {
            *text += '%';
            ++i;
            continue;
        }
        // %[0][width]d
        std::size_t j = i + 1;
        bool zero = j < path.size() && path[j] == '0';
        if (zero) ++j;
        int width = 0;
        while (j < path.size() && std::isdigit(static_cast<unsigned char>(path[j])) && width < 100)
            width = width * 10 + (path[j++] - '0');
        if (j >= path.size() || path[j] != 'd' || width > 9) {
            error = "'" + path +
                    "': a frame number pattern is %d or %0Nd such as %04d (N at most 9); write %% for '%'";
            return std::nullopt;
        }
        // printf's %4d pads with spaces: names that ffmpeg and most tools cannot read back.
        if (width > 0 && !zero) {
            error = "'" + path + "': %" + std::to_string(width) + "d would pad with spaces; write %0" +
                    std::to_string(width) + "d (zero-padded) or %d";
            return std::nullopt;
        }
        if (found) {
            error = "'" + path + "': only one %d frame number is allowed";
            return std::nullopt;
        }
        found = true;
        pattern.zeroPad = zero;
        pattern.width = width;
        text = &pattern.suffix;
        i = j;
    }
    if (!found) {
        error = "'" + path + "' has no %d frame number (for example frames/f_%04d.png)";
        return std::nullopt;
    }
    return pattern;
}

}  // namespace f2
