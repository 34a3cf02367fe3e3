// f2 language: the scene language's commands, and the files generated from
// its one table (the editors' TextMate grammar, the fuzzer's dictionary).
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "lsp/language_files.h"

namespace f2::cli {

namespace {

int fillTemplate(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::cerr << "f2 language: cannot read '" << path << "': " << std::strerror(errno) << '\n';
        return 1;
    }
    std::ostringstream text;
    text << in.rdbuf();
    std::string problem;
    const std::string filled = lsp::fillLanguageTemplate(text.str(), problem);
    if (!problem.empty()) {
        std::cerr << path << ":" << problem << '\n';
        return 1;
    }
    std::cout << filled;
    return 0;
}

int printLists() {
    for (std::string_view name : lsp::languageListNames()) {
        std::cout << name << ":";
        const std::vector<std::string> words = lsp::languageList(name).value_or(std::vector<std::string>{});
        for (const std::string& word : words) std::cout << ' ' << word;
        std::cout << '\n';
    }
    return 0;
}

}  // namespace

Command addLanguageCommand(CLI::App& app) {
    auto fill = std::make_shared<std::string>();
    auto lists = std::make_shared<bool>(false);
    CLI::App* sub = app.add_subcommand(
        "language",
        "Print the scene language's commands with their syntax (or, for tool makers, its word lists)");
    sub->add_option("--fill", *fill,
                    "Print TEMPLATE with each @f2:LIST@ replaced by that word list as a regular expression "
                    "alternation, and each line @f2:LIST:dict@ by one \"word\" line per word (how the "
                    "TextMate grammar and the fuzz dictionary are generated)")
        ->type_name("TEMPLATE");
    sub->add_flag("--lists", *lists, "Print the word lists a template may use")->excludes("--fill");
    return {sub, [fill, lists] {
                if (*lists) return printLists();
                if (!fill->empty()) return fillTemplate(*fill);
                std::cout << lsp::languageSummary();
                return 0;
            }};
}

}  // namespace f2::cli
