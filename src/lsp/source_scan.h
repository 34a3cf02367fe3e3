#pragma once
/// Variables and includes of a document (SPEC 9.4, 9.5), found in its text:
/// `/let NAME`, `/repeat NAME` define a variable; a name inside `( … )` or
/// `{ … }` that is not a function uses one; `/include PATH` names a file.
/// Textual, so it works on a document with errors and needs nothing from the
/// parser; a variable is known by its name across the document.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsp/text_document.h"

namespace f2::lsp {

struct VariableOccurrence {
    std::string name;
    int line = 0;                    ///< 0-based
    std::size_t begin = 0, end = 0;  ///< bytes in the line
    bool definition = false;         ///< the name after /let or /repeat
    bool loop = false;               ///< defined by /repeat
    int file = 0;                    ///< index into SceneSources::files (scene_sources.h)
    /// Reading order: the line's place when includes are read where they stand
    /// (the line itself for one document alone).
    std::uint32_t order = 0;
};

/// Every variable occurrence of the document, in text order.
std::vector<VariableOccurrence> scanVariables(const TextDocument& doc);

/// The definition a use at reading order `order` refers to: the nearest `/let`
/// before it or an enclosing `/repeat` (the nearest definition before), else
/// the first one; nullopt when no such name is defined.
std::optional<VariableOccurrence> definitionOf(const std::vector<VariableOccurrence>& all,
                                               std::string_view name, std::uint32_t order);

/// The path argument of an `/include` line (quotes removed) and its bytes in the line.
struct IncludePath {
    std::string path;
    std::size_t begin = 0, end = 0;  ///< the argument as written, quotes included
};
std::optional<IncludePath> includeOn(const TextDocument& doc, int line);

/// An include's file: relative paths from the directory of `documentPath`.
std::string resolveInclude(std::string_view documentPath, std::string_view path);

/// A `/repeat` or `/model` block of the document: the lines of its opening
/// command and of its `/end` (the last line when the `/end` is missing).
struct BlockLines {
    int start = 0, end = 0;  ///< 0-based
    bool model = false;      ///< a `/model` block (SPEC 10.1)
    bool closed = false;     ///< its `/end` is there
};
/// Every block of the document, in the order their `/end`s close them.
std::vector<BlockLines> blocksOf(const TextDocument& doc);

/// True when byte `byte` of `line` is inside `( … )` or `{ … }` (not in a comment).
bool insideExpression(std::string_view line, std::size_t byte);

}  // namespace f2::lsp
