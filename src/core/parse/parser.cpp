#include "core/parse/parser.h"

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/parse/language.h"
#include "core/parse/quoted_text.h"
#include "core/parse/scene_builder.h"
#include "core/parse/source_expander.h"

// The entry points: reading a file or a text, then the SceneBuilder
// (scene_builder.h) over the CommandReader (command_reader.h).

namespace f2 {

using parsing::SceneBuilder;

namespace {

ParseResult readError(const std::string& displayName, std::string message) {
    ParseResult result;
    result.diagnostics.push_back({{displayName, 1, 1}, Severity::Error, std::move(message)});
    result.files.push_back(displayName);
    return result;
}

/// Reads a whole stream, stopping one byte past the limit so that a huge or
/// endless input is never held in memory.
bool readStream(std::FILE* f, std::size_t limit, std::string& out, std::string& problem) {
    std::array<char, 1 << 16> buffer;
    for (;;) {
        const std::size_t got = std::fread(buffer.data(), 1, buffer.size(), f);
        if (got > 0) {
            if (out.size() + got > limit) {
                problem = "the input is larger than the limit of " + std::to_string(limit) + " bytes";
                return false;
            }
            out.append(buffer.data(), got);
        }
        if (got < buffer.size()) {
            if (std::ferror(f)) {
                problem = std::strerror(errno);
                return false;
            }
            return true;
        }
    }
}

}  // namespace

ParseResult parseScene(std::string_view text, std::string_view fileName, const ParseLimits& limits) {
    return SceneBuilder(fileName, limits, nullptr).run(text);
}

ParseResult parseScene(std::string_view text, std::string_view fileName, const ParseLimits& limits,
                       SymbolIndex& index) {
    index.clear();
    return SceneBuilder(fileName, limits, &index).run(text);
}

ParseResult parseScene(std::string_view text, std::string_view fileName, const ParseLimits& limits,
                       SymbolIndex& index, const SourceOverlay& overlay) {
    index.clear();
    SceneBuilder parser(fileName, limits, &index);
    parser.setOverlay(&overlay);
    return parser.run(text, fileIdentity(std::string(fileName)));
}

std::vector<std::string_view> commandNames() {
    std::vector<std::string_view> names;
    for (const CommandSpec& c : commands()) names.push_back(c.name);
    return names;
}

ParseResult parseScene(std::string_view text, std::string_view fileName) {
    return parseScene(text, fileName, ParseLimits{});
}

ParseResult parseSceneFile(const std::string& path, const ParseLimits& limits) {
    std::string text, problem;
    if (path == "-") {
        const std::string name = "<stdin>";
        errno = 0;
        if (!readStream(stdin, limits.maxSceneBytes, text, problem)) {
            return readError(name, "cannot read standard input: " + problem);
        }
        return parseScene(text, name, limits);
    }

    // Binary: CRLF is handled by the lexer. A FIFO or a directory is refused
    // without blocking on it.
    FileRead file = readSourceFile(path, limits.maxSceneBytes);
    if (!file.ok) return readError(path, "cannot read " + quotePath(path) + ": " + file.problem);
    return SceneBuilder(path, limits, nullptr).run(file.text, std::pair{file.device, file.inode});
}

ParseResult parseSceneFile(const std::string& path) { return parseSceneFile(path, ParseLimits{}); }

}  // namespace f2
