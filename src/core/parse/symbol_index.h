#pragma once
/// Where each name of a scene is created and used: an optional output of the
/// parser for tools that work on the source (the language server), filled
/// even when the scene has errors.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/parse/diagnostic.h"
#include "core/scene/scene_desc.h"

namespace f2 {

/// A token of the source: its place (1-based line, 1-based byte column) and length in bytes.
struct TokenSpan {
    SourceLoc loc;
    int length = 0;
};

/// An object as its creating command made it (no keys yet), and where.
struct IndexedObject {
    SceneObject object;
    TokenSpan name;     ///< the name argument of the creating command
    SourceLoc command;  ///< the command's first character
};

/// A named light (SPEC 10.2) as its command made it, and where.
struct IndexedLight {
    std::string name;
    std::string command;   ///< the light's command, such as "/point_light"
    TokenSpan nameSpan;    ///< the word after `name`
    SourceLoc commandLoc;  ///< the command's first character
};

/// A command argument that names an existing object (`r1`, or the `r1` of `r1.head`:
/// a part after the name is read from the source) or a named light.
struct NameUse {
    std::size_t object = 0;  ///< index into SymbolIndex::objects, or into `lights` when `light`
    TokenSpan name;          ///< the name only, without `.part`
    std::string command;     ///< the command it appears in, such as "/key"
    bool light = false;      ///< it names a light (SPEC 10.2)
};

/// A model type of the scene (SPEC 10.1) and where its `/model`, parts and
/// shapes are written (parallel to the type's parts and shapes).
struct IndexedModel {
    std::shared_ptr<const ModelType> type;
    TokenSpan name;  ///< the type's name after `/model`
    SourceLoc command;
    std::vector<TokenSpan> parts, shapes;  ///< a part's name after `/part`; a shape's `part.shape`
};

/// A command line that tools list as a symbol of the scene: `/camera`, lights.
struct IndexedCommand {
    std::string command;
    SourceLoc loc;
};

struct SymbolIndex {
    std::vector<IndexedObject> objects;  ///< in creation order
    std::vector<IndexedLight> lights;    ///< named lights, in creation order (SceneDesc::lightMotions' order)
    std::vector<NameUse> uses;           ///< in file order
    std::vector<IndexedCommand> commands;
    std::vector<IndexedModel> models;  ///< the scene's `/model` types, in file order

    void clear() { *this = SymbolIndex{}; }
    /// Keeps the commands listed as symbols (the camera and lights), ignores the rest.
    void noteCommand(std::string_view command, const SourceLoc& loc) {
        if (command == "/camera" || command == "/amb_light" || command == "/dir_light" ||
            command == "/point_light" || command == "/spot_light") {
            commands.push_back({std::string(command), loc});
        }
    }
};

}  // namespace f2
