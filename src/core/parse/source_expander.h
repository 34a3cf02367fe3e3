#pragma once
/// The front end of the scene language (SPEC 9.4, 9.5): reads the scene file
/// and the files it includes, runs `/let`, `/repeat … /end` and `/include`,
/// pairs `/model` with its `/end` (SPEC 10.1; the parser reads the block),
/// evaluates `( … )` arguments and `{ … }` in names, and hands the command
/// parser one logical line at a time. The command parser never sees those
/// four commands. Lines are produced on demand, so a loop of ten million
/// passes never holds more than one line in memory.
#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/parse/expression.h"
#include "core/parse/lexer.h"

namespace f2 {

/// A place in the expanded source.
struct SourcePos {
    int line = 0;    ///< 1-based, in its own file
    int column = 0;  ///< 1-based, in bytes
    int file = 0;    ///< index into SourceExpander::files(); 0 is the main file
    /// Ordinal of the line in reading order (each loop pass reads its lines
    /// again): sorts diagnostics across files and passes. 0 = before any line.
    std::uint32_t seq = 0;
    int length = 0;  ///< bytes of source from column it covers (a token's); 0: a point
};

/// How an argument was written.
enum class TokenForm {
    Word,        ///< as written, after `{ … }` substitution
    Expression,  ///< a `( … )`: `value` holds its value, `text` that value in decimal
    Failed,      ///< a `( … )` or `{ … }` whose error is already reported
    Compiled,    ///< a `/drive`'s `( … )` (SPEC 10.7): LogicalLine::compiled, `text` as written
};

struct LogicalToken {
    std::string_view text;
    std::string_view written;  ///< the token as written in the file
    int column = 0;            ///< 1-based byte column of the token as written
    TokenForm form = TokenForm::Word;
    double value = 0;
};

/// One command line for the command parser. `count` may exceed
/// kMaxStoredTokens; then only the first kMaxStoredTokens are stored.
struct LogicalLine {
    std::array<LogicalToken, kMaxStoredTokens> tokens{};
    int count = 0;
    SourcePos pos;         ///< the line (column 1)
    std::string_view raw;  ///< the line as written
    /// The code of the line's TokenForm::Compiled token, if it has one.
    ExpressionCode compiled;
};

/// The command as written, from its first token to the end of its last stored
/// one: the comment left out, the spaces between tokens kept (a no-break space
/// that glued two arguments together is found there).
std::string_view writtenCommand(const LogicalLine& line);

/// Limits of the expansion; the values come from ParseLimits.
struct ExpansionLimits {
    std::uint64_t maxLines = 0;  ///< lines read in all, each loop pass again
    std::uint64_t maxBytes = 0;  ///< bytes of those lines in all
    int maxLoopDepth = 0;
    int maxIncludeDepth = 0;
    std::size_t maxLineBytes = 0;  ///< one line
    std::size_t maxFileBytes = 0;  ///< all files read, together
};

/// Where the expander sends its errors (the command parser's report()).
class ExpansionSink {
   public:
    virtual ~ExpansionSink() = default;
    virtual void expansionError(SourcePos pos, std::string message) = 0;
    /// Whether `command` is one the receiver runs: the arguments of an unknown
    /// command are not evaluated, so its one error is not followed by theirs.
    virtual bool knowsCommand(std::string_view /*command*/) const { return true; }
};

/// Reading a file for the parser: a regular file only (a FIFO or a device is
/// refused without blocking on it), at most `maxBytes` bytes.
struct FileRead {
    bool ok = false;
    std::string text;
    std::string problem;                  ///< "No such file or directory", "it is a directory", ...
    std::uint64_t device = 0, inode = 0;  ///< the file's identity, to find include cycles
};
FileRead readSourceFile(const std::string& path, std::size_t maxBytes);

/// A file's (device, inode), if it is a regular file.
std::optional<std::pair<std::uint64_t, std::uint64_t>> fileIdentity(const std::string& path);

class SourceExpander {
   public:
    SourceExpander(const ExpansionLimits& limits, ExpansionSink& sink);
    ~SourceExpander();
    SourceExpander(const SourceExpander&) = delete;
    SourceExpander& operator=(const SourceExpander&) = delete;

    /// Starts with the main text. `name` is its name in diagnostics; relative
    /// includes are read from the directory part of `name` (the current
    /// directory if it has none, as for "<stdin>"). `identity` is the main
    /// file's (device, inode) when it is a file, so including it is a cycle.
    void start(std::string_view text, std::string name,
               std::optional<std::pair<std::uint64_t, std::uint64_t>> identity = std::nullopt);

    /// Texts read instead of the files on disk (by resolved path); the map
    /// must outlive the expander. None by default.
    void setOverlay(const std::map<std::string, std::string, std::less<>>* overlay) { overlay_ = overlay; }

    /// The next command line, or false at the end (or after a limit error).
    bool next(LogicalLine& line);

    /// Name of file `index` as diagnostics show it.
    const std::string& fileName(int index) const;
    /// Every file read or tried (a missing include too), the main file first.
    const std::vector<std::string>& files() const { return names_; }
    /// " (in /repeat i = 3, j = 1)" while lines of a loop are read, else "".
    std::string loopNote() const;
    /// Lines read in all, each loop pass and each include counted again.
    std::uint64_t linesRead() const { return linesRead_; }
    /// Lines in the files themselves, each file counted once.
    std::uint64_t linesInFiles() const { return linesInFiles_; }

    /// Where a `/model` block's lines start, to read them again (SPEC 10.6).
    struct BlockStart {
        const void* source = nullptr;           ///< the SourceFile, kept by the expander
        LineReader reader{std::string_view()};  ///< just after the `/model` line
        int nameIndex = 0;
    };
    /// The block whose `/model` line `next` returned last. Each block is a
    /// scope of variables: its `/let`s and loop variables, and the values
    /// setVariable gives before its first line, are gone after its `/end`.
    const BlockStart& lastModelBlock() const { return lastModelBlock_; }
    /// Sets a variable (a model's parameter, SPEC 10.6) in the current scope.
    void setVariable(std::string_view name, double value) { variables_.set(name, value); }
    /// Reads the lines of the block at `start` again, up to its `/end`
    /// (which `next` returns), in a scope of variables of their own.
    void replayModelBlock(const BlockStart& start);

   private:
    struct SourceFile;
    struct LoopInfo;
    struct OpenFile;
    struct OpenLoop;

    void tokenize(std::string_view text, LogicalLine& out);
    /// Evaluates the `( … )` and `{ … }` of tokens from `first` on; token
    /// `compiledAt`, a `( … )`, is compiled over a drive's inputs instead.
    bool evaluateTokens(LogicalLine& line, int first, int compiledAt = -1);
    std::optional<double> numberArgument(const LogicalLine& line, int i, bool& ok);
    /// Checks the variable of /let or /repeat; reports "… cannot be `cannotBe`" for pi.
    bool variableName(const LogicalToken& name, std::string_view cannotBe);
    void runLet(const LogicalLine& line);
    void runRepeat(const LogicalLine& line, int lineNumber);
    void runEnd(const LogicalLine& line);
    void runInclude(std::string_view raw, const LogicalLine& line);
    void skipLoop(const LoopInfo& info);
    int addFile(std::string name);
    const SourceFile* loadFile(const std::string& path, SourcePos at);
    void error(SourcePos pos, std::string message) { sink_.expansionError(pos, std::move(message)); }
    SourcePos at(int column) const;
    /// Where `token` is, with its written extent.
    SourcePos at(const LogicalToken& token) const;
    /// Where an expression's problem is, its text starting at `textColumn`.
    SourcePos inExpression(int textColumn, const ExpressionResult& result) const;

    ExpansionLimits limits_;
    ExpansionSink& sink_;
    const std::map<std::string, std::string, std::less<>>* overlay_ = nullptr;
    Variables variables_;
    std::vector<std::string> names_;
    std::deque<std::unique_ptr<SourceFile>> sources_;
    std::vector<OpenFile> fileStack_;
    std::vector<OpenLoop> loopStack_;
    /// Open `/model` blocks (SPEC 10.1): the depths of the file and loop
    /// stacks at their `/model`, so that the `/end` at those depths is theirs.
    struct ModelBlock {
        std::size_t fileDepth, loopDepth;
        Variables outside;    ///< the variables before the block, back after its `/end`
        bool replay = false;  ///< read again for an instance: its file frame ends at the `/end`
    };
    BlockStart lastModelBlock_;
    std::vector<ModelBlock> modelBlocks_;
    /// Whether an `/end` read now closes a model block rather than a loop.
    bool endsModel() const;
    std::uint64_t linesRead_ = 0, bytesRead_ = 0, linesInFiles_ = 0;
    std::size_t fileBytes_ = 0;
    bool stopped_ = false;
    int lineNumber_ = 0;
    std::string storage_;  ///< texts of substituted tokens of the current line
};

}  // namespace f2
