#pragma once
/// The files of a scene as the language server reads them: a document and every
/// file it includes (SPEC 9.5), followed in the text where each `/include`
/// stands, with their variables in reading order. Textual like source_scan.h,
/// so it works on a scene with errors; open documents' texts replace the files
/// on disk.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/parse/parser.h"
#include "lsp/source_scan.h"
#include "lsp/text_document.h"

namespace f2::lsp {

struct SceneFile {
    std::string path;
    TextDocument document;
};

/// An `/include` line of one file that reads another.
struct IncludeLink {
    int file = 0;    ///< the including file
    int line = 0;    ///< 0-based
    int target = 0;  ///< the included file
};

struct SceneSources {
    std::vector<SceneFile> files;  ///< [0] the document the scan started from
    std::vector<VariableOccurrence>
        variables;                      ///< every file's, in reading order (an include read twice: twice)
    std::vector<IncludeLink> includes;  ///< each link once

    /// Index of the file `path`, or -1.
    int find(std::string_view path) const;
    /// Reading order of a line (its first reading); beyond every order when
    /// the scan never reached it.
    std::uint32_t orderOf(int file, int line) const;
    /// True when `to` is read through the includes of `from` (or is `from`).
    bool reaches(int from, int to) const;
    /// For each file, whether it is read through the includes of `from` (or is `from`).
    std::vector<bool> reachableFrom(int from) const;

    /// Reading order of each line of each file, first reading.
    std::vector<std::vector<std::uint32_t>> firstOrder;
};

/// Limits of the scan, so that includes nested in a diamond 16 deep stay cheap.
constexpr std::uint64_t kMaxScannedLines = 2'000'000;
constexpr int kMaxScanDepth = 16;  ///< as the parser's include depth (SPEC 9.5)

/// Scans `document` (the file `path`) and what it includes. An include whose
/// path is an expression, a missing file and a cycle are not followed (the
/// parser reports them).
SceneSources scanScene(const std::string& path, const TextDocument& document, const SourceOverlay& open);

}  // namespace f2::lsp
