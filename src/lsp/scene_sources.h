#pragma once
/// The files of a scene as the language server sees them: a document and every
/// file it includes (SPEC 9.5), with their variables in reading order. Built
/// from the parser's symbol index (core/parse/symbol_index.h), its one pass
/// over the scene, so it holds what that pass read: the texts of open
/// documents in place of their files, every line of a scene with errors, up to
/// a limit that stops the parse. A loop of no pass is not read (SPEC 9.4):
/// its body's variables are not known, so hover and definition on them answer
/// nothing, as for a name the scene does not define.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/parse/symbol_index.h"
#include "lsp/text_document.h"

namespace f2::lsp {

struct SceneFile {
    std::string path;
    TextDocument document;
};

struct VariableOccurrence {
    std::string name;
    int line = 0;                    ///< 0-based
    std::size_t begin = 0, end = 0;  ///< bytes in the line
    bool definition = false;         ///< the name after /let or /repeat
    bool loop = false;               ///< defined by /repeat
    int file = 0;                    ///< index into SceneSources::files
    std::uint32_t order = 0;         ///< the first reading of its line
    std::optional<double> value;     ///< a definition's value then (IndexedVariable::value)
};

/// An `/include` line of one file, each written place once.
struct IncludeLink {
    int file = 0;                    ///< the including file
    int line = 0;                    ///< 0-based
    std::size_t begin = 0, end = 0;  ///< the path as written, quotes included: bytes in the line
    int target = -1;                 ///< the included file, or -1 when it was not read
    std::string path;                ///< the file the path resolves to
};

struct SceneSources {
    std::vector<SceneFile> files;               ///< [0] the file parsed as the scene
    std::vector<VariableOccurrence> variables;  ///< each written place once, in reading order
    std::vector<IncludeLink> includes;

    /// Index of the file `path`, or -1.
    int find(std::string_view path) const;
    /// Reading order of a line (its first reading). A line never read (in a
    /// loop of no pass) has the order of the last line read before it in its
    /// file; beyond every order when there is none.
    std::uint32_t orderOf(int file, int line) const;
    /// True when `to` is read through the includes of `from` (or is `from`).
    bool reaches(int from, int to) const;
    /// For each file, whether it is read through the includes of `from` (or is `from`).
    std::vector<bool> reachableFrom(int from) const;

    /// Reading order of each line of each file, first reading (IndexedFile::firstOrder).
    std::vector<std::vector<std::uint32_t>> firstOrder;
};

/// The scene's files, variables and includes as the parse that filled `index` read them.
SceneSources sourcesOf(const SymbolIndex& index);

/// The definition a use at reading order `order` refers to: the nearest `/let`
/// before it or an enclosing `/repeat` (the nearest definition before), else
/// the first one; nullopt when no such name is defined.
std::optional<VariableOccurrence> definitionOf(const std::vector<VariableOccurrence>& all,
                                               std::string_view name, std::uint32_t order);

}  // namespace f2::lsp
