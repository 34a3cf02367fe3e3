#pragma once
/// The scene language (SPEC 2-7 and 9). The parser reports and never exits:
/// the caller decides what to do with the diagnostics. `/let`, `/repeat`,
/// `/include` and expressions are expanded first (source_expander.h).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/parse/diagnostic.h"
#include "core/scene/limits.h"
#include "core/scene/scene_desc.h"

namespace f2 {

struct ParseResult {
    /// Set only when there is no error: a scene with an error is never partly used.
    std::optional<SceneDesc> scene;
    /// Every error and warning, in reading order (loops and includes expanded).
    std::vector<Diagnostic> diagnostics;
    /// Every file read or tried, the main one first, then each `/include`d
    /// one once, as diagnostics name them (the viewer watches them all).
    std::vector<std::string> files;
    /// Lines read in all, each loop pass and each include counted again
    /// (SPEC 9.5), and lines in the files themselves, each file once.
    std::uint64_t linesRead = 0;
    std::uint64_t linesInFiles = 0;

    bool ok() const { return scene.has_value(); }
};

/// Parses scene text; `fileName` names it in diagnostics, and a relative
/// `/include` is read from its directory (the current one if it has none, as
/// for "<stdin>").
ParseResult parseScene(std::string_view text, std::string_view fileName);

/// Limits that keep a hostile scene from exhausting the machine (SPEC 7, and
/// docs/scene-language.md for the ones SPEC leaves open). Each is checked
/// before anything is allocated for it and breaking one is an error.
struct ParseLimits {
    int maxImageSide = kMaxImageSide;
    long long maxImagePixels = kMaxImagePixels;
    std::size_t maxObjects = 1'000'000;  ///< a robot or human counts as one
    int maxKeyFrame = kMaxKeyFrame;
    std::size_t maxKeyLines = 10'000'000;
    std::size_t maxLights = 1000;  ///< light commands of every kind together
    int maxFps = 1000;
    std::size_t maxLineBytes = std::size_t{1} << 20;     ///< 1 MiB
    std::size_t maxSceneBytes = std::size_t{256} << 20;  ///< 256 MiB, all included files together
    /// SPEC 9.5: lines read in all after loops and includes are expanded.
    std::uint64_t maxExpandedLines = 10'000'000;
    /// Bytes of those lines, so that a loop over long lines stays bounded (choice).
    std::uint64_t maxExpandedBytes = std::uint64_t{1} << 30;
    int maxLoopDepth = 64;     ///< SPEC 9.5
    int maxIncludeDepth = 16;  ///< SPEC 9.5
    /// Parsing stops after this many errors; further warnings are counted, not kept.
    std::size_t maxErrors = 1000;
    std::size_t maxWarnings = 1000;
};

/// parseScene with other limits (tests use small ones).
ParseResult parseScene(std::string_view text, std::string_view fileName, const ParseLimits& limits);

struct SymbolIndex;
/// parseScene that also fills `index` (cleared first) with where each name is
/// created and used, for tools that work on the source (core/parse/symbol_index.h).
ParseResult parseScene(std::string_view text, std::string_view fileName, const ParseLimits& limits,
                       SymbolIndex& index);

/// Texts that stand in for files on disk while parsing (an editor's unsaved
/// buffers), keyed by the path an `/include` resolves to (lexically normal).
using SourceOverlay = std::map<std::string, std::string, std::less<>>;

/// parseScene for editors: fills `index` as above, reads an included file from
/// `overlay` when it is there (from disk otherwise), and takes the text to be
/// the file `fileName` when that file exists, so including it is a cycle.
ParseResult parseScene(std::string_view text, std::string_view fileName, const ParseLimits& limits,
                       SymbolIndex& index, const SourceOverlay& overlay);

/// Every command of the language ("/camera", ...), in the parser's table order.
std::vector<std::string_view> commandNames();

/// Reads and parses a file; "-" reads standard input. A missing, unreadable or
/// non-regular file gives one error at `FILE:1:1`.
ParseResult parseSceneFile(const std::string& path);
ParseResult parseSceneFile(const std::string& path, const ParseLimits& limits);

}  // namespace f2
