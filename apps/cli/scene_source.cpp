#include "scene_source.h"

#include <iostream>

#include "core/parse/parser.h"
#include "core/scene/default_scene.h"
#include "io/option_value.h"

namespace f2::cli {

std::optional<LoadedScene> loadScene(const std::string& path) {
    bool embedded = path.empty();
    ParseResult result = embedded ? parseScene(defaultSceneText(), kDefaultSceneName) : parseSceneFile(path);
    for (const Diagnostic& d : result.diagnostics) std::cerr << d.format() << '\n';
    if (!result.ok()) return std::nullopt;
    return LoadedScene{std::move(*result.scene), embedded ? std::string(kDefaultSceneName) : path,
                       std::move(result.files), result.linesInFiles, result.linesRead};
}

bool parseSize(const std::string& text, int& width, int& height, std::string& error) {
    const io::OptionValue<io::ImageSize> size = io::readImageSize(text);
    if (!size.ok()) {
        error = "--size: " + size.error;
        return false;
    }
    width = size.value.width;
    height = size.value.height;
    return true;
}

}  // namespace f2::cli
