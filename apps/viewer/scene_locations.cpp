#include "scene_locations.h"

#include <map>
#include <tuple>

#include "core/parse/symbol_index.h"

namespace f2::viewer {

SceneLocations SceneLocations::fromIndex(const SymbolIndex& index) {
    SceneLocations locations;
    locations.objects_.reserve(index.objects.size());
    // How many objects each line made, by (file, line).
    std::map<std::pair<std::string_view, int>, int> perLine;
    for (const IndexedObject& o : index.objects) ++perLine[{o.command.file, o.command.line}];
    std::map<std::pair<std::string_view, int>, int> before;
    for (const IndexedObject& o : index.objects) {
        const std::pair<std::string_view, int> line{o.command.file, o.command.line};
        locations.objects_.try_emplace(o.object.name, CreatedAt{o.command, perLine[line], before[line]++});
    }
    return locations;
}

const CreatedAt* SceneLocations::object(const std::string& name) const {
    const auto it = objects_.find(name);
    return it == objects_.end() ? nullptr : &it->second;
}

}  // namespace f2::viewer
