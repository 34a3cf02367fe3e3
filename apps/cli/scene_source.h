#pragma once
/// Loading the scene named on the command line, with diagnostics on stderr.
#include <optional>
#include <string>

#include "core/scene/scene_desc.h"

namespace f2::cli {

/// Path given on the command line; empty means the embedded default scene.
struct LoadedScene {
    SceneDesc scene;
    std::string name;  ///< for messages: the path or the default scene's name
};

/// Parses `path` ("" = embedded default, "-" = stdin), prints every diagnostic
/// to stderr; nullopt when there was an error.
std::optional<LoadedScene> loadScene(const std::string& path);

/// Parses "WxH" (e.g. 1280x720) within the SPEC's image limits.
bool parseSize(const std::string& text, int& width, int& height, std::string& error);

}  // namespace f2::cli
