#pragma once
/// The scene language (SPEC 2-7). The parser reports and never exits: the
/// caller decides what to do with the diagnostics.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/parse/diagnostic.h"
#include "core/scene/limits.h"
#include "core/scene/scene_desc.h"

namespace f2 {

struct ParseResult {
    /// Set only when there is no error: a scene with an error is never partly used.
    std::optional<SceneDesc> scene;
    /// Every error and warning, in file order.
    std::vector<Diagnostic> diagnostics;

    bool ok() const { return scene.has_value(); }
};

/// Parses scene text; `fileName` is used only in diagnostics.
ParseResult parseScene(std::string_view text, std::string_view fileName);

/// Limits that keep a hostile scene from exhausting the machine (SPEC 7, and
/// docs/scene-language.md for the ones SPEC leaves open). Each is checked
/// before anything is allocated for it and breaking one is an error.
struct ParseLimits {
    int maxImageSide = kMaxImageSide;
    long long maxImagePixels = kMaxImagePixels;
    std::size_t maxObjects = 1'000'000;  ///< a robot or human counts as one
    int maxKeyFrame = kMaxKeyFrame;
    std::size_t maxKeyLines = 10'000'000;
    int maxFps = 1000;
    std::size_t maxLineBytes = std::size_t{1} << 20;     ///< 1 MiB
    std::size_t maxSceneBytes = std::size_t{256} << 20;  ///< 256 MiB
    /// Parsing stops after this many errors; further warnings are counted, not kept.
    std::size_t maxErrors = 1000;
    std::size_t maxWarnings = 1000;
};

/// parseScene with other limits (tests use small ones).
ParseResult parseScene(std::string_view text, std::string_view fileName, const ParseLimits& limits);

/// Reads and parses a file; "-" reads standard input. A missing, unreadable or
/// non-regular file gives one error at `FILE:1:1`.
ParseResult parseSceneFile(const std::string& path);
ParseResult parseSceneFile(const std::string& path, const ParseLimits& limits);

}  // namespace f2
