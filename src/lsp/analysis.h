#pragma once
/// A parsed document and what the features ask of it: the symbol under the
/// cursor, objects by name, key counts. Rebuilt on every change.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/parse/parser.h"
#include "core/parse/symbol_index.h"
#include "lsp/source_scan.h"
#include "lsp/text_document.h"

namespace f2::lsp {

/// The file path of a `file://` URI (percent-decoded), or the URI itself for
/// other schemes (an unsaved "untitled:" document).
std::string pathFromUri(std::string_view uri);
/// A `file://` URI for an absolute path.
std::string uriFromPath(std::string_view path);

struct Analysis {
    std::string uri;
    std::string path;  ///< the file name given to the parser (diagnostics name it)
    TextDocument document;
    ParseResult result;
    SymbolIndex index;
    std::vector<VariableOccurrence> variables;  ///< of this document's text

    /// True when a place is in this document (not in an included file).
    bool inDocument(const SourceLoc& loc) const { return loc.file == path; }
    /// Range of a token span in this document.
    Range rangeOf(const TokenSpan& span) const {
        return document.range(span.loc.line, span.loc.column, span.length);
    }
};

Analysis analyze(std::string uri, TextDocument document);

/// What is under a position.
struct SymbolAt {
    enum class Kind { None, Command, Object, Part, Variable, Include } kind = Kind::None;
    std::size_t object = 0;    ///< Object and Part: index into index.objects
    int part = -1;             ///< Part: PartId index
    std::string_view command;  ///< Command: its name
    Range range;               ///< the token (or the name or part within it)
    std::string text;          ///< Variable: its name; Include: the path as written
};

SymbolAt symbolAt(const Analysis& a, Position p);

/// The object named `name` in the index (the first one created), if any.
std::optional<std::size_t> findObject(const SymbolIndex& index, std::string_view name);

/// Keys of an object: [0] its own, [1 + PartId] each part's. From the scene
/// when it parsed; otherwise the `/key` lines that name it in this document.
std::array<std::size_t, 5> keyCounts(const Analysis& a, std::size_t object);

/// A part name (body, head, lhand, rhand) right after `name` at a use or
/// definition in this document: its PartId index and byte range in the line.
struct PartSuffix {
    int part = -1;
    std::size_t begin = 0, end = 0;  ///< bytes in the line
};
std::optional<PartSuffix> partAfter(const Analysis& a, const TokenSpan& name);

/// Whether `name` is valid as a new object or variable name.
bool isValidName(std::string_view name);

/// What the parser of this build accepts beyond the first edition, probed once
/// by parsing small scenes, so the server follows the language as it grows.
struct LanguageFeatures {
    std::vector<std::string_view> commands;  ///< every command the parser knows
    std::vector<std::string_view> modes;     ///< interpolation modes /interp accepts
    bool cameraTarget = false;               ///< `/key 0 camera` is valid
    bool keyModes = false;                   ///< a `/key` may end with a mode

    bool knows(std::string_view command) const;
};
const LanguageFeatures& languageFeatures();

}  // namespace f2::lsp
