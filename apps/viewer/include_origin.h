#pragma once
/// Which `/include` line of the main file made an object whose creating line
/// is in an included file (directly or through other includes). The symbol
/// index names only the creating line; when a file is included by several
/// lines, or by a line in a `/repeat` loop, the include that made one
/// instance is found by reading the source again as the parser does (the
/// core's SourceExpander), with a marker before each `/include` of the main file.
#include <QString>
#include <string>

#include "core/parse/diagnostic.h"

namespace f2::viewer {

/// The 1-based line of `mainText` (named `mainName`, as diagnostics name it)
/// whose `/include` made the `instance`-th (0-based, in creation order) object
/// that the command at `created` creates, or 0 when `created` is in the main
/// file or no include made it.
int includingLine(const QString& mainText, const std::string& mainName, const SourceLoc& created,
                  int instance);

/// An included file's name as the status bar shows it: relative to the
/// folder of the scene file `scenePath` when it is inside it, else as given.
QString includedFileName(const std::string& file, const QString& scenePath);

}  // namespace f2::viewer
