#pragma once
/// The subcommands of `f2`: each registers its options on the app and returns
/// the subcommand with the function that runs it.
#include <CLI/CLI.hpp>
#include <functional>

namespace f2::cli {

struct Command {
    CLI::App* app;
    std::function<int()> run;  ///< exit code
};

Command addRenderCommand(CLI::App& app);
Command addCheckCommand(CLI::App& app);
Command addInfoCommand(CLI::App& app);
Command addExportCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addLspCommand(CLI::App& app);
Command addLanguageCommand(CLI::App& app);

}  // namespace f2::cli
