#pragma once
/// Where the objects of a parsed scene and the shapes of its `/model` types
/// are created in its source, from the parser's own symbol index
/// (core/parse/symbol_index.h): names made by `/repeat` loops, `{ }`
/// expressions and `/include`d files are found too, which a search of the
/// text cannot do.
#include <string>
#include <unordered_map>
#include <vector>

#include "core/parse/diagnostic.h"

namespace f2 {
struct SymbolIndex;
}

namespace f2::viewer {

/// The command that created an object.
struct CreatedAt {
    SourceLoc loc;     ///< its first character; `file` as diagnostics name it
    int sameLine = 1;  ///< objects that line created: more than one means a
                       ///< `/repeat` loop (or a file included more than once)
    int instance = 0;  ///< objects that line created before this one
};

class SceneLocations {
   public:
    /// The creating commands of the objects `index` lists.
    static SceneLocations fromIndex(const SymbolIndex& index);

    /// Where object `name` was created, if the scene has it.
    const CreatedAt* object(const std::string& name) const;
    std::size_t size() const { return objects_.size(); }
    /// Where shape `shape` of the model type `type` is created in its `/model`
    /// block (SPEC 10.1): its `part.shape` argument. Nothing for the robot
    /// and the human, which no line defines.
    const SourceLoc* shape(const std::string& type, int shape) const;

   private:
    std::unordered_map<std::string, CreatedAt> objects_;
    std::unordered_map<std::string, std::vector<SourceLoc>> shapes_;  // by model type
};

}  // namespace f2::viewer
