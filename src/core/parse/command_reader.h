#pragma once
/// Reading a scene's commands (docs/design.md, "The front end"): the lines
/// as the SourceExpander gives them (loops and includes run, expressions
/// evaluated), each argument read as a number, a key time, a pose, a colour
/// with its place in the source, and every diagnostic with its place, its
/// loop note and its repeats. The scene builder (scene_builder.h) gives the
/// commands their meaning; this class knows nothing of a scene.

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/math/vec3.h"
#include "core/parse/diagnostic.h"
#include "core/parse/language.h"
#include "core/parse/lexer.h"
#include "core/parse/parser.h"
#include "core/parse/source_expander.h"
#include "core/parse/symbol_index.h"
#include "core/parse/unusual_char.h"
#include "core/scene/scene_desc.h"

namespace f2::parsing {

/// A place in the source: file, line, column and reading order (SPEC 9.5).
using Pos = SourcePos;

/// A key time as written (SPEC 10.4): frames, or seconds (`2.5s`, `(expr)s`).
struct KeyTime {
    double value = 0;
    bool seconds = false;
};

class CommandReader : protected ExpansionSink {
   public:
    CommandReader(std::string_view fileName, const ParseLimits& limits);

    /// Texts read instead of included files on disk (source_expander.h).
    void setOverlay(const SourceOverlay* overlay) { expander_.setOverlay(overlay); }

   protected:
    /// The diagnostics (repeats counted, in reading order) and what was read;
    /// the caller adds the scene.
    ParseResult finishReading();

    void expansionError(Pos pos, std::string message) override {
        report(Severity::Error, pos, std::move(message), LoopNote::Always);
    }

    /// "3:5", or "FILE:3:5" when `p` is in another file than the current line.
    std::string posText(Pos p) const;

    // Diagnostics
    /// Whether a message gets the loop values: the expander's always (it reports
    /// on the line it reads), the parser's when `pos` is on the line being read.
    enum class LoopNote { OnThisLine, Always };

    /// Reports a diagnostic at `pos`. The same message at the same place again
    /// (a later loop pass, a file included twice) is counted on the first
    /// one, not printed again.
    void report(Severity severity, Pos pos, std::string message, LoopNote noted = LoopNote::OnThisLine);

    void push(Diagnostic diagnostic, Pos pos, bool inLoop = false);

    void error(Pos pos, std::string message) { report(Severity::Error, pos, std::move(message)); }

    void warning(Pos pos, std::string message) { report(Severity::Warning, pos, std::move(message)); }

    // Tokens of the current line
    int argCount() const { return tokens_.count - 1; }

    std::string_view commandText() const { return tokens_.tokens[0].text; }

    Pos at(int column) const;

    /// Where token i of the line is, with its written extent (so a diagnostic there covers it).
    /// A token past the stored ones (a line longer than kMaxStoredTokens) is
    /// reported at the last stored one: never read past the array.
    Pos tokenPos(int i) const;

    Pos commandPos() const { return tokenPos(0); }

    const LogicalToken& storedToken(int i) const {
        return tokens_.tokens[static_cast<std::size_t>(std::clamp(i, 0, kMaxStoredTokens - 1))];
    }

    const LogicalToken& argToken(int i) const { return storedToken(i + 1); }

    std::string_view arg(int i) const { return argToken(i).text; }

    Pos argPos(int i) const { return tokenPos(i + 1); }

    /// A `( … )` or `{ … }` of argument i failed; its error is already reported.
    bool failed(int i) const { return argToken(i).form == TokenForm::Failed; }

    /// The line from its first token to the end of its last stored one (no comment), as written.
    std::string_view commandLine() const { return writtenCommand(tokens_); }

    /// `message` with a note naming an invisible or unusual character of
    /// `text` (found at `pos`): a no-break space looks like a space in the message.
    static std::string noteCharacters(std::string message, std::string_view text, Pos pos) {
        return withUnusualCharacterNote(std::move(message), text, pos.column);
    }

    /// Checks the argument count against the allowed ones ("3, 6 or 9"),
    /// not counting `optionArgs` arguments of options the command found.
    bool expectArgs(std::span<const int> allowed, int optionArgs = 0);
    bool expectArgs(std::initializer_list<int> allowed, int optionArgs = 0) {
        return expectArgs(std::span<const int>(allowed.begin(), allowed.size()), optionArgs);
    }

    // Argument readers: on a problem they report it, clear `ok` and return a harmless value.
    double number(int i, bool& ok);

    /// The number of seconds in `2.5s` (an expression `(…)s` arrives so too), if `text` is one.
    static std::optional<double> secondsValue(std::string_view text);

    /// A key time (SPEC 10.4): a number of frames >= 0, fractions allowed, or
    /// seconds. Seconds are checked against the frame limit once `/fps` is known.
    KeyTime keyTime(int i, bool& ok);

    float real(int i, bool& ok) { return static_cast<float>(number(i, ok)); }

    float positive(int i, std::string_view what, bool& ok);

    float nonNegative(int i, std::string_view what, bool& ok);

    /// A whole number in [lo, hi]; "1e3" and "-0" count as whole.
    int whole(int i, std::string_view what, int lo, int hi, bool& ok);

    Vec3 vec3(int first, bool& ok) { return {real(first, ok), real(first + 1, ok), real(first + 2, ok)}; }

    Pose pose(int first, bool withRotation, bool& ok);

    Color8 color(int first, bool& ok);

    // Commands
    /// Reports a repeated single-use command; remembers the first one.
    bool firstOnly(std::optional<Pos>& seen);

    /// Whether argument i is a word that may be a mode (not a number, not an expression).
    bool isWordArgument(int i) const {
        return argToken(i).form == TokenForm::Word && !arg(i).empty() && isNameStart(arg(i).front());
    }

    // Symbol index (optional output)
    SourceLoc sourceLoc(Pos pos) const { return {expander_.fileName(pos.file), pos.line, pos.column}; }

    /// The name at `pos` as written: `r{i}` for the name r3 (up to a '.' outside braces).
    TokenSpan span(Pos pos, std::string_view name) const;

    std::string_view fileName_;
    ParseLimits limits_;
    SourceExpander expander_;
    std::vector<Diagnostic> diagnostics_;
    std::vector<Pos> order_;  ///< parallel to diagnostics_: where each was found

    /// Parallel to diagnostics_: how often it came again at its place, and
    /// whether its place was a loop pass.
    struct Repeats {
        std::uint64_t count = 0;
        bool inLoop = false;
    };

    std::vector<Repeats> repeats_;
    std::unordered_map<std::string, std::size_t> firstAtPlace_;  ///< place + message -> index
    std::size_t errors_ = 0, warnings_ = 0, droppedWarnings_ = 0;
    Pos firstDroppedWarning_;
    bool stopped_ = false;
    LogicalLine tokens_;

    /// " (in /lamp L1)" while a block is read again for an instance (SPEC 10.6).
    std::string instanceNote_;
};

}  // namespace f2::parsing
