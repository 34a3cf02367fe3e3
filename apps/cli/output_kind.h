#pragma once
/// What `f2 render -o NAME` writes, decided from the name alone: one PNG, a
/// PNG to standard output (`-`), a numbered PNG sequence (`%04d`) or a video
/// (.mp4, .webm, .gif); an existing device or FIFO (`/dev/null`) takes one
/// PNG. Anything else is refused with the known kinds, so a typo never
/// silently writes PNG data under a .jpg name.
#include <optional>
#include <string>

#include "io/frame_pattern.h"
#include "io/video_encoder.h"

namespace f2::cli {

struct OutputKind {
    enum class Kind { Image, StandardOutput, Sequence, Video };
    Kind kind = Kind::Image;
    VideoFormat video = VideoFormat::Mp4;  ///< for Kind::Video
    FramePattern pattern;                  ///< for Kind::Sequence

    bool isAnimation() const { return kind == Kind::Sequence || kind == Kind::Video; }
};

/// Classifies `name`; nullopt with a usage `error` for an unknown extension,
/// a bad frame pattern or a directory.
std::optional<OutputKind> classifyOutput(const std::string& name, std::string& error);

}  // namespace f2::cli
