#include "output_kind.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace f2::cli {

namespace {
constexpr const char* kKnownKinds =
    "f2 writes .png (one image, or a numbered sequence such as f_%04d.png), .mp4, .webm, .gif, "
    "or - (one PNG to standard output)";

std::string lowerExtension(const std::string& name) {
    std::string ext = std::filesystem::path(name).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}
}  // namespace

std::optional<OutputKind> classifyOutput(const std::string& name, std::string& error) {
    OutputKind target;
    if (name == "-") {
        target.kind = OutputKind::Kind::StandardOutput;
        return target;
    }
    std::error_code ec;
    if (name.back() == '/' || std::filesystem::is_directory(name, ec)) {
        const std::string dir = name.back() == '/' ? name : name + "/";
        const bool exists = std::filesystem::exists(name, ec);
        error = "'" + name + (exists ? "' is a directory" : "' names a directory (it ends in '/')") +
                "; name a file in it (" + dir + "f2.png) or a numbered sequence (" + dir + "f_%04d.png)";
        return std::nullopt;
    }
    if (auto video = videoFormatForPath(name)) {
        target.kind = OutputKind::Kind::Video;
        target.video = *video;
        return target;
    }
    // A device, FIFO or socket (`-o /dev/null`) takes one PNG whatever its name.
    const auto status = std::filesystem::status(name, ec);
    if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) return target;
    const std::string ext = lowerExtension(name);
    if (looksLikeFramePattern(name)) {
        auto pattern = parseFramePattern(name, error);
        if (!pattern) return std::nullopt;
        target.kind = OutputKind::Kind::Sequence;
        target.pattern = *pattern;
    }
    if (ext != ".png") {
        error = "'" + name +
                "': " + (ext.empty() ? std::string("no extension") : "unknown output type '" + ext + "'") +
                "; " + kKnownKinds;
        return std::nullopt;
    }
    return target;
}

}  // namespace f2::cli
