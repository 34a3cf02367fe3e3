#include "lsp/language_files.h"

#include <algorithm>
#include <array>

#include "core/parse/expression.h"
#include "core/parse/language.h"
#include "core/scene/models.h"
#include "core/scene/scene_desc.h"

namespace f2::lsp {

namespace {

/// The commands for which `keep` holds, without their '/'.
template <typename Keep>
std::vector<std::string> commandWords(Keep keep) {
    std::vector<std::string> words;
    for (const CommandSpec& c : commands()) {
        if (keep(c)) words.emplace_back(c.name.substr(1));
    }
    return words;
}

struct NamedList {
    std::string_view name;
    std::vector<std::string> (*words)();
};

const std::array<NamedList, 18> kLists = {{
    {"commands", [] { return commandWords([](const CommandSpec&) { return true; }); }},
    // As written in a scene: "/camera", … (the fuzz dictionary's entries).
    {"slashed-commands",
     [] {
         std::vector<std::string> words;
         for (const CommandSpec& c : commands()) words.emplace_back(c.name);
         return words;
     }},
    {"creating",
     [] { return commandWords([](const CommandSpec& c) { return c.group == CommandGroup::Creating; }); }},
    // The commands the parser runs that create nothing: settings, looks, motion.
    {"scene-commands",
     [] {
         return commandWords([](const CommandSpec& c) {
             return c.group != CommandGroup::Creating && c.group != CommandGroup::Source;
         });
     }},
    {"variable-commands",
     [] {
         return commandWords([](const CommandSpec& c) { return c.argumentKind(0) == ArgKind::Variable; });
     }},
    {"path-commands",
     [] { return commandWords([](const CommandSpec& c) { return c.argumentKind(0) == ArgKind::Path; }); }},
    {"block-end-commands",
     [] {
         return commandWords(
             [](const CommandSpec& c) { return c.group == CommandGroup::Source && c.args.empty(); });
     }},
    {"light-options",
     [] {
         std::vector<std::string> words;
         for (const LightOptionSpec& o : lightOptions()) words.emplace_back(o.word);
         return words;
     }},
    {"material-options", [] { return std::vector<std::string>{std::string(kEmitWord)}; }},
    {"attach-words",
     [] {
         return std::vector<std::string>{std::string(kAtWord), std::string(kWorldName)};
     }},
    {"key-properties",
     [] {
         std::vector<std::string> words;
         for (const KeyPropertySpec& p : keyProperties()) words.emplace_back(p.word);
         return words;
     }},
    {"drive-channels",
     [] {
         std::vector<std::string> words;
         for (std::string_view c : driveChannelNames()) words.emplace_back(c);
         return words;
     }},
    {"drive-inputs",
     [] {
         std::vector<std::string> words;
         for (std::string_view v : kDriveInputs) words.emplace_back(v);
         return words;
     }},
    {"modes",
     [] {
         std::vector<std::string> words;
         for (Interpolation m : interpolationModes()) words.emplace_back(interpolationName(m));
         return words;
     }},
    {"parts",
     [] {
         std::vector<std::string> words;
         // The built-in models' parts (a scene's own models name their own).
         for (const ModelPart& p : robotModel()->parts) words.push_back(p.name);
         return words;
     }},
    {"camera", [] { return std::vector<std::string>{std::string(kCameraName)}; }},
    {"functions",
     [] {
         std::vector<std::string> words;
         for (std::string_view f : expressionFunctionNames()) words.emplace_back(f);
         return words;
     }},
    {"constants",
     [] {
         std::vector<std::string> words;
         for (std::string_view v : kPredefinedVariables) words.emplace_back(v);
         return words;
     }},
}};

/// `word` as a regular expression inside a JSON string: a metacharacter gets
/// a backslash, written `\\` in JSON (no word of the language has one today).
std::string regexEscaped(std::string_view word) {
    std::string out;
    for (char c : word) {
        if (std::string_view("\\^$.|?*+()[]{}").find(c) != std::string_view::npos) out += "\\\\";
        out += c;
    }
    return out;
}

std::string alternation(std::vector<std::string> words) {
    // Longest first: an alternation tries its branches in order.
    std::stable_sort(words.begin(), words.end(),
                     [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : "|") + regexEscaped(w);
    return out;
}

}  // namespace

std::vector<std::string_view> languageListNames() {
    std::vector<std::string_view> names;
    for (const NamedList& l : kLists) names.push_back(l.name);
    return names;
}

std::optional<std::vector<std::string>> languageList(std::string_view name) {
    for (const NamedList& l : kLists) {
        if (l.name == name) return l.words();
    }
    return std::nullopt;
}

std::string fillLanguageTemplate(std::string_view text, std::string& problem) {
    static constexpr std::string_view kOpen = "@f2:";
    std::string out;
    std::size_t at = 0;
    int line = 1;
    while (at < text.size()) {
        const std::size_t open = text.find(kOpen, at);
        if (open == std::string_view::npos) {
            out.append(text.substr(at));
            break;
        }
        line += static_cast<int>(std::count(text.begin() + static_cast<std::ptrdiff_t>(at),
                                            text.begin() + static_cast<std::ptrdiff_t>(open), '\n'));
        out.append(text.substr(at, open - at));
        const std::size_t close = text.find('@', open + kOpen.size());
        const std::size_t newline = text.find('\n', open);
        const std::size_t lineStart =
            text.rfind('\n', open) == std::string_view::npos ? 0 : text.rfind('\n', open) + 1;
        const std::string place =
            std::to_string(line) + ":" + std::to_string(open - lineStart + 1) + ": error: ";
        if (close == std::string_view::npos || (newline != std::string_view::npos && close > newline)) {
            problem = place + "'@f2:' without its closing '@'";
            return {};
        }
        std::string_view name = text.substr(open + kOpen.size(), close - open - kOpen.size());
        const bool dict = name.ends_with(":dict");
        if (dict) name.remove_suffix(5);
        const std::optional<std::vector<std::string>> words = languageList(name);
        if (!words) {
            problem = place + "unknown list '" + std::string(name) + "' (f2 language --lists names them)";
            return {};
        }
        if (dict) {
            for (std::size_t i = 0; i < words->size(); ++i)
                out += (i == 0 ? "\"" : "\n\"") + (*words)[i] + "\"";
        } else {
            out += alternation(*words);
        }
        at = close + 1;
    }
    return out;
}

std::string languageSummary() {
    std::string out;
    for (const CommandSpec& c : commands()) {
        out += std::string(c.syntax) + "\n    " + std::string(c.meaning) + "\n";
    }
    return out;
}

}  // namespace f2::lsp
