// f2 lsp: the language server for editors, over standard input and output.
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <memory>

#include "commands.h"
#include "lsp/stdio_transport.h"

namespace f2::cli {

Command addLspCommand(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "lsp",
        "Run the language server (Language Server Protocol over standard input and output) for editors");
    auto stdio = std::make_shared<bool>(false);
    sub->add_flag("--stdio", *stdio,
                  "Accepted for editors that pass it; standard input and output are always used");
    return {sub, [stdio] {
                // The client closing the pipe must end the server, not kill it mid-write.
                std::signal(SIGPIPE, SIG_IGN);
                return f2::lsp::runServer(STDIN_FILENO, STDOUT_FILENO, stderr);
            }};
}

}  // namespace f2::cli
