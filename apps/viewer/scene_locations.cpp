#include "scene_locations.h"

#include <map>
#include <tuple>

#include "core/parse/symbol_index.h"
#include "core/scene/models.h"

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
    for (const IndexedModel& m : index.models) {
        if (!m.type) continue;
        std::vector<SourceLoc>& shapes = locations.shapes_[m.type->name];
        for (const TokenSpan& s : m.shapes) shapes.push_back(s.loc);
    }
    return locations;
}

const SourceLoc* SceneLocations::shape(const std::string& type, int shape) const {
    const auto it = shapes_.find(type);
    if (it == shapes_.end() || shape < 0 || std::size_t(shape) >= it->second.size()) return nullptr;
    return &it->second[std::size_t(shape)];
}

const CreatedAt* SceneLocations::object(const std::string& name) const {
    const auto it = objects_.find(name);
    return it == objects_.end() ? nullptr : &it->second;
}

}  // namespace f2::viewer
