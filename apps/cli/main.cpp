// f2 — the command-line front door. Argument parsing only; the work is in f2::core.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include "commands.h"
#include "options.h"

namespace {
/// "unknown option '--bogus'", "unexpected arguments 'b' 'c'": the words CLI11 did not take, in order.
std::string unexpectedArguments(const std::vector<std::string>& extras) {
    bool allOptions = true;
    std::string quoted;
    for (const std::string& word : extras) {
        allOptions = allOptions && word.size() > 1 && word[0] == '-';
        quoted += (quoted.empty() ? "'" : " '") + word + "'";
    }
    const bool many = extras.size() > 1;
    return (allOptions ? (many ? "unknown options " : "unknown option ")
                       : (many ? "unexpected arguments " : "unexpected argument ")) +
           quoted;
}

/// A command that did its work but whose standard output was lost (`f2 info >
/// /dev/full`, a full disk) has failed: exit 1 with the reason, as coreutils
/// do, instead of 0 without the output it promised.
int checkedStandardOutput(const std::string& command, int status) {
    errno = 0;
    const bool lost = std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout.good();
    if (!lost || status != 0) return status;
    const int cause = errno;
    std::cerr << "f2 " << command << ": cannot write to standard output"
              << (cause != 0 ? std::string(": ") + std::strerror(cause) : std::string()) << '\n';
    return 1;
}
}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "f2 — ray-traced key-frame animation of scenes with the robot F-2.\n"
        "Without a SCENE argument every command uses the embedded default scene (scenes/demo.f2).",
        "f2"};
    app.set_version_flag("--version", "f2 0.1.0");
    app.require_subcommand(1);

    std::vector<f2::cli::Command> commands = {
        f2::cli::addRenderCommand(app),   f2::cli::addCheckCommand(app), f2::cli::addInfoCommand(app),
        f2::cli::addExportCommand(app),   f2::cli::addBenchCommand(app), f2::cli::addLspCommand(app),
        f2::cli::addLanguageCommand(app),
    };
    // `f2` alone: the short help (the commands), as a usage error.
    if (argc == 1) {
        std::cerr << app.help();
        return f2::cli::kUsageError;
    }
    // CLI11 would only say "a subcommand is required"; name the unknown option or word.
    std::string names;
    bool known = false;
    for (const auto& command : commands) {
        known = known || command.app->get_name() == argv[1];
        names += (names.empty() ? "" : ", ") + command.app->get_name();
    }
    const std::string first = argv[1];
    if (first.rfind('-', 0) == 0 && first != "-h" && first != "--help" && first != "--version")
        return f2::cli::usageError(
            "", "unknown option '" + first + "'; a command comes first (" + names + "), then its options");
    if (first.rfind('-', 0) != 0 && !known)
        return f2::cli::usageError("", "unknown command '" + first + "' (expected " + names + ")");
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);  // --help, --version
    } catch (const CLI::ExtrasError&) {
        // CLI11 lists the extra arguments in reverse ("c b" for `f2 render a b c`): name them in order.
        std::string command;
        std::vector<std::string> extras = app.remaining();
        for (const CLI::App* sub : app.get_subcommands()) {
            command = sub->get_name();
            extras = sub->remaining();
        }
        return f2::cli::usageError(command, unexpectedArguments(extras));
    } catch (const CLI::ParseError& e) {
        // CLI11's own exit codes (105, 109, ...) would break the promise of 2
        // for every usage error; its message names the option.
        std::string command;
        for (const CLI::App* sub : app.get_subcommands()) command = sub->get_name();
        // "--aa: 1 required INT missing" is CLI11's jargon for an option given without its value.
        static const std::regex kMissingValue(R"(^(\S+): [0-9]+ required \S+ missing$)");
        return f2::cli::usageError(command,
                                   std::regex_replace(e.what(), kMissingValue, "$1: the value is missing"));
    }
    for (const auto& command : commands)
        if (command.app->parsed()) return checkedStandardOutput(command.app->get_name(), command.run());
    return 1;
}
