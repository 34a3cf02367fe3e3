#include "lsp/scene_sources.h"

#include <algorithm>
#include <limits>

#include "core/parse/source_expander.h"

namespace f2::lsp {

namespace {

constexpr std::uint32_t kNotReached = std::numeric_limits<std::uint32_t>::max();

class Scanner {
   public:
    Scanner(SceneSources& out, const SourceOverlay& open) : out_(out), open_(open) {}

    void walk(int file, int depth) {
        stack_.push_back(file);
        // Copies: `files` grows while the walk goes on.
        const std::vector<VariableOccurrence> own = ownVariables_[static_cast<std::size_t>(file)];
        auto next = own.begin();
        const int lines = out_.files[static_cast<std::size_t>(file)].document.lineCount();
        for (int line = 0; line < lines && visited_ < kMaxScannedLines; ++line, ++visited_) {
            const auto order = static_cast<std::uint32_t>(visited_);
            auto& first = out_.firstOrder[static_cast<std::size_t>(file)][static_cast<std::size_t>(line)];
            if (first == kNotReached) first = order;
            for (; next != own.end() && next->line == line; ++next) {
                VariableOccurrence v = *next;
                v.file = file;
                v.order = order;
                out_.variables.push_back(std::move(v));
            }
            const auto include = includeOn(out_.files[static_cast<std::size_t>(file)].document, line);
            // A path with an expression is known only to the parser.
            if (!include || include->path.find_first_of("{(") != std::string::npos) continue;
            const int target =
                load(resolveInclude(out_.files[static_cast<std::size_t>(file)].path, include->path));
            if (target < 0) continue;
            const IncludeLink link{file, line, target};
            if (std::none_of(out_.includes.begin(), out_.includes.end(), [&](const IncludeLink& l) {
                    return l.file == link.file && l.line == link.line;
                })) {
                out_.includes.push_back(link);
            }
            if (depth < kMaxScanDepth && std::find(stack_.begin(), stack_.end(), target) == stack_.end()) {
                walk(target, depth + 1);
            }
        }
        stack_.pop_back();
    }

    int add(std::string path, TextDocument document) {
        ownVariables_.push_back(scanVariables(document));
        out_.firstOrder.emplace_back(static_cast<std::size_t>(document.lineCount()), kNotReached);
        out_.files.push_back({std::move(path), std::move(document)});
        return static_cast<int>(out_.files.size() - 1);
    }

   private:
    /// The file's index, reading it first (from the open texts, else from disk); -1 if unreadable.
    int load(const std::string& path) {
        if (const int known = out_.find(path); known >= 0) return known;
        if (const auto it = open_.find(path); it != open_.end())
            return add(path, TextDocument(it->second, 0));
        const std::size_t budget =
            ParseLimits{}.maxSceneBytes - std::min(ParseLimits{}.maxSceneBytes, bytes_);
        FileRead read = readSourceFile(path, budget);
        if (!read.ok) return -1;
        bytes_ += read.text.size();
        return add(path, TextDocument(std::move(read.text), 0));
    }

    SceneSources& out_;
    const SourceOverlay& open_;
    std::vector<std::vector<VariableOccurrence>> ownVariables_;
    std::vector<int> stack_;
    std::uint64_t visited_ = 0;
    std::size_t bytes_ = 0;
};

}  // namespace

int SceneSources::find(std::string_view path) const {
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (files[i].path == path) return static_cast<int>(i);
    }
    return -1;
}

std::uint32_t SceneSources::orderOf(int file, int line) const {
    if (file < 0 || static_cast<std::size_t>(file) >= firstOrder.size()) return kNotReached;
    const auto& lines = firstOrder[static_cast<std::size_t>(file)];
    if (line < 0 || static_cast<std::size_t>(line) >= lines.size()) return kNotReached;
    return lines[static_cast<std::size_t>(line)];
}

bool SceneSources::reaches(int from, int to) const {
    if (from == to) return true;
    return to >= 0 && static_cast<std::size_t>(to) < files.size() &&
           reachableFrom(from)[static_cast<std::size_t>(to)];
}

std::vector<bool> SceneSources::reachableFrom(int from) const {
    std::vector<bool> seen(files.size(), false);
    if (from < 0 || static_cast<std::size_t>(from) >= files.size()) return seen;
    std::vector<std::vector<int>> targets(files.size());
    for (const IncludeLink& l : includes) targets[static_cast<std::size_t>(l.file)].push_back(l.target);
    std::vector<int> todo{from};
    seen[static_cast<std::size_t>(from)] = true;
    while (!todo.empty()) {
        const int f = todo.back();
        todo.pop_back();
        for (const int t : targets[static_cast<std::size_t>(f)]) {
            if (!seen[static_cast<std::size_t>(t)]) {
                seen[static_cast<std::size_t>(t)] = true;
                todo.push_back(t);
            }
        }
    }
    return seen;
}

SceneSources scanScene(const std::string& path, const TextDocument& document, const SourceOverlay& open) {
    SceneSources sources;
    Scanner scanner(sources, open);
    scanner.walk(scanner.add(path, document), 0);
    return sources;
}

}  // namespace f2::lsp
