#pragma once
/// Where each name of a scene is created and used: an optional output of the
/// parser for tools that work on the source (the language server), filled
/// even when the scene has errors.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
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

/// A variable where it is written (SPEC 9.4): the name after `/let` or
/// `/repeat` (a definition), or a name inside a `( … )` or `{ … }` argument
/// that is not a function (a use; `frame` and `time` of a `/drive` too).
struct IndexedVariable {
    std::string name;
    TokenSpan span;
    bool definition = false;
    bool loop = false;        ///< defined by `/repeat`
    std::uint32_t order = 0;  ///< the first reading of its line (SourcePos::seq)
    /// A definition's value at that reading (a loop's first pass); none when it failed.
    std::optional<double> value;
};

/// An `/include` line and the file its path resolves to.
struct IndexedInclude {
    TokenSpan path;      ///< the path as written, quotes included
    std::string target;  ///< the file, as diagnostics name it
    bool read = false;   ///< the file was read (an include cycle too); false: missing, unreadable
};

/// A file of the scene as the parser read it, the main one first.
struct IndexedFile {
    static constexpr std::uint32_t kNotRead = std::numeric_limits<std::uint32_t>::max();
    std::string path;  ///< as diagnostics name it
    std::string text;
    /// By 0-based line: its first reading (SourcePos::seq), kNotRead for a
    /// line never read (a loop of no pass, after a limit stopped the parse).
    std::vector<std::uint32_t> firstOrder;
};

struct SymbolIndex {
    std::vector<IndexedObject> objects;  ///< in creation order
    std::vector<IndexedLight> lights;    ///< named lights, in creation order (SceneDesc::lightMotions' order)
    std::vector<NameUse> uses;           ///< in file order
    std::vector<IndexedCommand> commands;
    std::vector<IndexedModel> models;  ///< the scene's `/model` types, in file order
    /// Filled, when `recordSources` is set, by the source expander at the
    /// first reading of each line, so that a loop body read many times lists
    /// each place once; in reading order.
    std::vector<IndexedVariable> variables;
    std::vector<IndexedInclude> includes;
    std::vector<IndexedFile> files;
    /// Whether to fill the three above: the language server does; the viewer
    /// would only pay a copy of every file for them.
    bool recordSources = false;

    /// Empties the index; what it records stays as set.
    void clear() {
        const bool sources = recordSources;
        *this = SymbolIndex{};
        recordSources = sources;
    }
    /// Keeps the commands listed as symbols (the camera and lights), ignores the rest.
    void noteCommand(std::string_view command, const SourceLoc& loc) {
        if (command == "/camera" || command == "/amb_light" || command == "/dir_light" ||
            command == "/point_light" || command == "/spot_light") {
            commands.push_back({std::string(command), loc});
        }
    }
};

}  // namespace f2
