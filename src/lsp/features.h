#pragma once
/// The language features: each answers one LSP request from an Analysis
/// (completion.cpp, hover.cpp, navigation.cpp, outline.cpp, key_format.cpp).
#include <string>

#include "lsp/analysis.h"
#include "lsp/protocol.h"

namespace f2::lsp {

/// Diagnostics of the analysis grouped by document URI (this one first, always
/// present, possibly empty), as `publishDiagnostics` params.
Json publishDiagnostics(const Analysis& a);

/// textDocument/completion: a CompletionItem array.
Json completion(const Analysis& a, Position p);

/// textDocument/hover: a Hover, or null.
Json hover(const Analysis& a, Position p);

/// textDocument/definition: a Location, or null.
Json definition(const Analysis& a, Position p);
/// textDocument/references: a Location array (null when nothing is there).
Json references(const Analysis& a, Position p, bool includeDeclaration);
/// textDocument/prepareRename: the name's range and text, or null.
Json prepareRename(const Analysis& a, Position p);
/// textDocument/rename: a WorkspaceEdit; throws RequestError for a bad new name.
Json rename(const Analysis& a, Position p, const std::string& newName);

/// textDocument/documentSymbol: DocumentSymbol array.
Json documentSymbols(const Analysis& a);
/// textDocument/foldingRange: `/repeat` … `/end` blocks.
Json foldingRanges(const Analysis& a);

/// textDocument/formatting: TextEdits aligning runs of `/key` lines into columns.
Json formatKeys(const Analysis& a);

}  // namespace f2::lsp
