#pragma once
/// What the cursor needs from the text of the open document itself, line by
/// line: whether it is inside an expression, the blocks to fold, where a path
/// being typed points. The scene's variables and includes come from the
/// parser's one pass instead (scene_sources.h). Folding stays textual so that
/// every `/repeat … /end` folds, a loop of no pass too (the parser skips it).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsp/text_document.h"

namespace f2::lsp {

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
