#pragma once
/// A parsed document and what the features ask of it: the symbol under the
/// cursor, objects by name, key counts. Rebuilt on every change.
#include <array>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/parse/parser.h"
#include "core/parse/symbol_index.h"
#include "lsp/scene_sources.h"
#include "lsp/source_scan.h"
#include "lsp/text_document.h"

namespace f2::lsp {

/// The file path of a `file://` URI (percent-decoded), or the URI itself for
/// other schemes (an unsaved "untitled:" document).
std::string pathFromUri(std::string_view uri);
/// A `file://` URI for an absolute path.
std::string uriFromPath(std::string_view path);

/// The URIs the client gave open documents, by path (a client may spell a
/// path differently from uriFromPath). One per server, shared by every
/// analysis it makes and kept current: the analysing thread writes it while
/// requests read it on the message thread, so each call locks.
class OpenUris {
   public:
    /// The URI of the open document whose file is `path`, if one is open.
    std::optional<std::string> find(std::string_view path) const;
    void set(const std::string& path, const std::string& uri);
    void erase(const std::string& path);

   private:
    mutable std::mutex mutex_;
    std::map<std::string, std::string, std::less<>> uris_;
};

/// A document and the scene it belongs to. The scene is the document itself,
/// or (`root`) an open document that includes it: then names and variables
/// of the including file are known here, and errors are those of the file as
/// that scene reads it.
struct Analysis {
    std::string uri;
    std::string path;  ///< this document's file name (diagnostics name it)
    std::string root;  ///< the file parsed as the scene: `path`, or a file that includes it
    TextDocument document;
    ParseResult result;
    SymbolIndex index;
    SceneSources sources;  ///< the scene's files from `root`, their variables in reading order (from `index`)
    int self = 0;          ///< this document in sources.files
    /// The URIs of open documents, shared by every document of a server.
    /// Null: none known.
    std::shared_ptr<const OpenUris> openUris;

    /// True when a place is in this document (not in an included file).
    bool inDocument(const SourceLoc& loc) const { return loc.file == path; }
    /// Range of a token span in this document.
    Range rangeOf(const TokenSpan& span) const {
        return document.range(span.loc.line, span.loc.column, span.length);
    }
    /// URI of a file of the scene (this document's own for it).
    std::string uriOf(std::string_view file) const;
    /// The text of a file of the scene, if the parser read it.
    const TextDocument* textOf(std::string_view file) const;
    /// Range of a token span in any file of the scene (bytes as UTF-16 when
    /// the file's text is unknown).
    Range anyRangeOf(const TokenSpan& span) const;
    /// This document's variable occurrences, in line order.
    std::vector<const VariableOccurrence*> ownVariables() const;
};

/// Analyses a document. `open`: the texts of open documents, which replace
/// the files on disk; `root`: the path of an open document that includes this
/// one (empty: the document is its own scene).
Analysis analyze(std::string uri, TextDocument document, const SourceOverlay& open = {},
                 const std::string& root = {});

/// What is under a position.
struct SymbolAt {
    /// Shape: `name.part.shape` (SPEC 10.1); Model: a model type's name, after
    /// `/model` or as an instance's command word (`/lamp`); ModelPart and
    /// ModelShape: a part or shape named inside its indexed `/model` block.
    enum class Kind {
        None,
        Command,
        Object,
        Part,
        Shape,
        Variable,
        Include,
        Camera,
        Light,
        Model,
        ModelPart,
        ModelShape
    } kind = Kind::None;
    /// Object, Part and Shape: index into index.objects; Light: into index.lights;
    /// Include: into sources.includes.
    std::size_t object = 0;
    int part = -1;             ///< Part, Shape and ModelPart: index among the model's parts
    std::string_view command;  ///< Command: its name
    Range range;               ///< the token (or the name, part or shape within it)
    std::string text;  ///< Variable: its name; Include: the file it resolves to; Model and members: the type
    int shape = -1;    ///< Shape and ModelShape: index among the model's shapes
};

SymbolAt symbolAt(const Analysis& a, Position p);

/// The object named `name` in the index (the first one created), if any.
std::optional<std::size_t> findObject(const SymbolIndex& index, std::string_view name);
/// The named light `name` in the index (SPEC 10.2), if any.
std::optional<std::size_t> findLight(const SymbolIndex& index, std::string_view name);

/// Keys of an object: [0] its own, [1 + part] each part's of a model. From the
/// scene when it parsed; otherwise the `/key` lines that name it in this document.
std::vector<std::size_t> keyCounts(const Analysis& a, std::size_t object);

/// A part name of object `object`'s model right after `name` at a use or
/// definition in this document: its index among the parts and byte range in
/// the line, and the shape after it (`name.part.shape`) if one is named.
struct PartSuffix {
    int part = -1;
    std::size_t begin = 0, end = 0;  ///< bytes in the line
    int shape = -1;
    std::size_t shapeBegin = 0, shapeEnd = 0;
};
std::optional<PartSuffix> partAfter(const Analysis& a, const TokenSpan& name, std::size_t object);

}  // namespace f2::lsp
