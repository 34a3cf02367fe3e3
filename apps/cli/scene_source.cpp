#include "scene_source.h"

#include <charconv>
#include <iostream>

#include "core/parse/parser.h"
#include "core/scene/default_scene.h"
#include "core/scene/limits.h"

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
    auto x = text.find('x');
    const char* begin = text.data();
    const char* end = begin + text.size();
    int w = 0, h = 0;
    if (x == std::string::npos || std::from_chars(begin, begin + x, w).ptr != begin + x ||
        std::from_chars(begin + x + 1, end, h).ptr != end) {
        error = "--size: expected WIDTHxHEIGHT such as 800x600, got '" + text + "'";
        return false;
    }
    if (!imageSizeAllowed(w, h)) {
        error = "--size: " + text + " is outside 1.." + std::to_string(kMaxImageSide) + " a side and " +
                std::to_string(kMaxImagePixels) + " pixels in all";
        return false;
    }
    width = w;
    height = h;
    return true;
}

}  // namespace f2::cli
