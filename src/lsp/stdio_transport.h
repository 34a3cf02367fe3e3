#pragma once
/// Runs the language server over two file descriptors (standard input and
/// output for `f2 lsp`).
#include <cstdio>

namespace f2::lsp {

/// Reads framed messages from `in` and writes replies to `out` until the
/// `exit` notification or the end of input; problems are logged to `log` as
/// lines. Returns the exit code (0 after a `shutdown` request, else 1).
int runServer(int in, int out, std::FILE* log);

}  // namespace f2::lsp
