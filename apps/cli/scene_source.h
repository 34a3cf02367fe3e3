#pragma once
/// Loading the scene named on the command line, with diagnostics on stderr.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/scene/scene_desc.h"

namespace f2::cli {

/// Path given on the command line; empty means the embedded default scene.
struct LoadedScene {
    SceneDesc scene;
    std::string name;  ///< for messages: the path or the default scene's name
    /// The files read (the main one, then every /include) and how many lines
    /// they hold and were read with loops and includes expanded (SPEC 9.5).
    std::vector<std::string> files;
    std::uint64_t linesInFiles = 0, linesRead = 0;
};

/// Parses `path` ("" = embedded default, "-" = stdin), prints every diagnostic
/// to stderr; nullopt when there was an error.
std::optional<LoadedScene> loadScene(const std::string& path);

/// Parses "WxH" (e.g. 1280x720) within the SPEC's image limits.
bool parseSize(const std::string& text, int& width, int& height, std::string& error);

}  // namespace f2::cli
