#include "core/parse/parser.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <numeric>
#include <unordered_map>

#include "core/parse/expression.h"
#include "core/parse/language.h"
#include "core/parse/lexer.h"
#include "core/parse/number.h"
#include "core/parse/quoted_text.h"
#include "core/parse/source_expander.h"
#include "core/parse/suggest.h"
#include "core/parse/symbol_index.h"
#include "core/parse/unusual_char.h"
#include "core/scene/models.h"

namespace f2 {

namespace {

/// Total work (distance table cells) spent on "did you mean" for names, so
/// that a file with a million objects and many unknown names stays fast.
constexpr std::size_t kMaxNameSuggestWork = 50'000'000;

/// A place in the source: file, line, column and reading order (SPEC 9.5).
using Pos = SourcePos;

/// The command closest to a mistyped one, if it is close enough to be a typo.
std::string_view suggestCommand(std::string_view word) {
    if (word.size() > kMaxSuggestLength) return {};
    // A cut-short name ("/amb light" for "/amb_light") is a likely mistake too.
    if (word.size() >= 3) {
        for (const CommandSpec& c : commands()) {
            if (c.name.starts_with(word)) return c.name;
        }
    }
    std::string_view best;
    std::size_t bestDistance = 3;  // at most two edits
    for (const CommandSpec& c : commands()) {
        const std::size_t d = editDistance(word, c.name);
        if (d < bestDistance) {
            bestDistance = d;
            best = c.name;
        }
    }
    return best;
}

struct StringHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const noexcept { return std::hash<std::string_view>{}(s); }
};

/// A command's target: an object, one part or shape of a model, the camera or a named light.
struct Target {
    std::size_t object = 0;
    int part = -1;        ///< index among the model's parts, or -1 for the object itself
    bool camera = false;  ///< the scene camera (SPEC 9.1); `object` and `part` unused
    int light = -1;       ///< a named light (SPEC 10.2): SceneDesc::lightMotions index; `object` unused
    int shape = -1;       ///< a shape of the model (`f2.head.leye`, SPEC 10.1), or -1
};

/// A key for the per-target books: object, part and shape in one number.
std::uint64_t slotOf(const Target& t) {
    return std::uint64_t(t.object) << 20 | std::uint64_t(t.part + 1) << 10 | std::uint64_t(t.shape + 1);
}

/// Whether a command accepts `camera` as its target.
enum class CameraTarget : bool { Refused, Accepted };
/// Whether a command accepts a named light as its target (SPEC 10.2).
enum class LightTarget : bool { Refused, Accepted };
/// Whether a command accepts a model's shape as its target (SPEC 10.1: looks and
/// colour or visible keys only).
enum class ShapeTarget : bool { Refused, Accepted };

/// What a track holds: the pose (none) or a property (SPEC 10.3).
using TrackProperty = std::optional<KeyProperty>;

/// Parse-time bookkeeping of one track: where each key came from, for the
/// duplicate-key warning. Parallel to Track::keys.
struct TrackBook {
    Target target;
    TrackProperty property;
    std::vector<Pos> origins;
    bool sorted = true;  ///< keys arrived in increasing frame order so far
    /// Keys whose time is still in seconds (SPEC 10.4), turned into frames at
    /// the end of the file, when `/fps` is known.
    std::vector<std::uint32_t> inSeconds;
};

/// A key time as written (SPEC 10.4): frames, or seconds (`2.5s`, `(expr)s`).
struct KeyTime {
    double value = 0;
    bool seconds = false;
};

/// An `/attach <name> <target> at <t>` (SPEC 10.7), kept until the end of
/// the file, when its time is in frames.
struct AttachChangeBook {
    std::uint32_t object = 0;
    KeyTime time;
    std::optional<FrameRef> mount;  ///< none: `world`
    std::string targetText;         ///< as written, for messages
    Pos command, timePos;
};

/// Parse-time bookkeeping of one object (its tracks' books are kept by
/// target: Parser::poseTrackBooks_ and the like).
struct ObjectBook {
    Pos defined;
    std::optional<Pos> attached;  ///< where its `/attach` is
    std::uint32_t loopNote = 0;  ///< the loop pass it was defined in: Parser::loopNotes_ index + 1, 0 if none
};

/// A `/model` block being read (SPEC 10.1).
struct ModelBuild {
    std::shared_ptr<ModelType> type;
    Pos defined;                   ///< its `/model`
    Pos namePos;                   ///< its type's name there
    std::size_t errorsBefore = 0;  ///< errors reported before it: one inside makes "no shapes" a follow-on
    bool named = false;            ///< its name is valid and new: the type is registered at `/end`
    int nested = 0;                ///< `/model` lines inside it (each an error) whose `/end` is still to come
    IndexedModel indexed;
    /// Read again for an instance (SPEC 10.6): the type whose names it must give; not registered.
    std::shared_ptr<const ModelType> readFor;
};

/// What addObject needs of a creating command's line, taken before a model's
/// block is read again for the instance (SPEC 10.6) and the line is gone.
struct ObjectLine {
    std::string name;
    Pos namePos, command;
    TokenSpan nameSpan;
    std::uint32_t loopNote = 0;
};

/// A model type that instances may use: the robot, the human, or a `/model` of the file.
struct TypeBook {
    std::shared_ptr<const ModelType> type;
    std::optional<Pos> defined;  ///< none for the robot and the human
    /// Where its block's lines start, read again for an instance that sets a parameter (SPEC 10.6).
    SourceExpander::BlockStart start;
};

/// Parse-time bookkeeping of one named light (SPEC 10.2).
struct LightBook {
    Pos defined;
    std::uint32_t loopNote = 0;             ///< as ObjectBook::loopNote
    int poseBook = -1, intensityBook = -1;  ///< Parser::trackBooks_ indices, -1 if none
    std::optional<Pos> interp, attached;
};

/// Where a `/caption`'s times stand and whether they are in seconds: they
/// become frames at the end of the file, then `to` must follow `from`.
struct CaptionBook {
    Pos from, to;
    bool fromInSeconds = false, toInSeconds = false;
};

/// A `/key` of the camera, kept until the end of the file: a key without
/// numbers takes `/camera`'s pose, wherever `/camera` stands (SPEC 9.1).
struct CameraKey {
    KeyTime time;
    std::optional<Pose> pose;
    std::optional<Easing> mode;
    Pos origin;
};

ExpansionLimits expansionLimits(const ParseLimits& limits) {
    ExpansionLimits e;
    e.maxLines = limits.maxExpandedLines;
    e.maxBytes = limits.maxExpandedBytes;
    e.maxLoopDepth = limits.maxLoopDepth;
    e.maxIncludeDepth = limits.maxIncludeDepth;
    e.maxLineBytes = limits.maxLineBytes;
    e.maxFileBytes = limits.maxSceneBytes;
    return e;
}

/// The rides at one time as a rooted forest, each object under the object it
/// rides on, which links, cuts and finds the top of a tree in amortized
/// O(log n) (a link-cut tree: Sleator and Tarjan; splay trees over the
/// preferred paths, no reversal since only tops are linked). Lets
/// `/attach … at` check cycles per interval in O(k log n) for k changes.
class RideForest {
   public:
    explicit RideForest(std::size_t n) : nodes_(n + 1) {}

    /// `child`, the top of its tree, now rides on `parent` (not in its tree).
    void link(std::uint32_t child, std::uint32_t parent) {
        const std::uint32_t c = child + 1;
        access(c);
        nodes_[c].parent = parent + 1;
    }
    /// `child` rides on nothing now (it may ride on nothing already).
    void cut(std::uint32_t child) {
        const std::uint32_t c = child + 1;
        access(c);
        if (const std::uint32_t above = nodes_[c].kid[0]) {
            nodes_[above].parent = 0;
            nodes_[c].kid[0] = 0;
        }
    }
    /// The top of the tree `x` is in: the object its chain of rides ends at.
    std::uint32_t top(std::uint32_t x) {
        std::uint32_t v = x + 1;
        access(v);
        while (nodes_[v].kid[0]) v = nodes_[v].kid[0];
        splay(v);
        return v - 1;
    }

   private:
    struct Node {
        std::uint32_t parent = 0;            ///< in its splay tree, or the path's parent at a splay root
        std::array<std::uint32_t, 2> kid{};  ///< 0: nearer the top, 1: farther
    };
    bool isSplayRoot(std::uint32_t x) const {
        const Node& p = nodes_[nodes_[x].parent];
        return nodes_[x].parent == 0 || (p.kid[0] != x && p.kid[1] != x);
    }
    void rotate(std::uint32_t x) {
        const std::uint32_t p = nodes_[x].parent, g = nodes_[p].parent;
        const int side = nodes_[p].kid[1] == x;
        if (!isSplayRoot(p)) nodes_[g].kid[nodes_[g].kid[1] == p] = x;
        nodes_[x].parent = g;
        const std::uint32_t moved = nodes_[x].kid[1 - side];
        nodes_[p].kid[side] = moved;
        if (moved) nodes_[moved].parent = p;
        nodes_[x].kid[1 - side] = p;
        nodes_[p].parent = x;
    }
    void splay(std::uint32_t x) {
        while (!isSplayRoot(x)) {
            const std::uint32_t p = nodes_[x].parent;
            if (!isSplayRoot(p)) {
                const std::uint32_t g = nodes_[p].parent;
                rotate((nodes_[g].kid[1] == p) == (nodes_[p].kid[1] == x) ? p : x);
            }
            rotate(x);
        }
    }
    /// Makes the path from x's top to x preferred, x at its splay root with nothing below it.
    void access(std::uint32_t x) {
        for (std::uint32_t below = 0, v = x; v; below = v, v = nodes_[v].parent) {
            splay(v);
            nodes_[v].kid[1] = below;
        }
        splay(x);
    }

    std::vector<Node> nodes_;  ///< object i is node i + 1; node 0 is none
};

// Parser
/// The commands of the scene; /let, /repeat, /end and /include are run by the
/// SourceExpander before a line gets here.
class Parser : private ExpansionSink {
   public:
    Parser(std::string_view fileName, const ParseLimits& limits, SymbolIndex* index)
        : fileName_(fileName), limits_(limits), index_(index), expander_(expansionLimits(limits), *this) {}

    /// Texts read instead of included files on disk (source_expander.h).
    void setOverlay(const SourceOverlay* overlay) { expander_.setOverlay(overlay); }

    /// `identity`: the main file's (device, inode), when it is a file.
    ParseResult run(std::string_view text,
                    std::optional<std::pair<std::uint64_t, std::uint64_t>> identity = std::nullopt) {
        const bool tooLarge = text.size() > limits_.maxSceneBytes;
        expander_.start(tooLarge ? std::string_view() : text, std::string(fileName_), identity);
        if (tooLarge) {
            error({1, 1}, "the scene is " + std::to_string(text.size()) + " bytes, more than the limit of " +
                              std::to_string(limits_.maxSceneBytes) + " bytes");
            return finish();
        }
        while (!stopped_ && expander_.next(tokens_)) parseLine();
        addCameraKeys();
        finishDrives();
        convertSecondsToFrames();
        checkAttachChanges();
        sortUnsortedTracks();
        applyInterpToPropertyTracks();
        orderColourTracks();
        orderAttachments();
        if (errors_ == 0) warnAboutTheWholeScene();
        return finish();
    }

   private:
    void expansionError(Pos pos, std::string message) override {
        report(Severity::Error, pos, std::move(message), LoopNote::Always);
    }
    bool knowsCommand(std::string_view command) const override {
        const CommandSpec* c = findCommand(command);
        return (c && c->group != CommandGroup::Source) || typeOfCommand(command) != nullptr;
    }

    /// The model type `/<type>` creates an instance of, or null.
    const TypeBook* typeOfCommand(std::string_view command) const {
        if (!command.starts_with('/')) return nullptr;
        const auto it = types_.find(command.substr(1));
        return it == types_.end() ? nullptr : &it->second;
    }

    /// "3:5", or "FILE:3:5" when `p` is in another file than the current line.
    std::string posText(Pos p) const {
        std::string s = std::to_string(p.line) + ":" + std::to_string(p.column);
        return p.file == tokens_.pos.file ? s : expander_.fileName(p.file) + ":" + s;
    }

    // Diagnostics
    /// Whether a message gets the loop values: the expander's always (it reports
    /// on the line it reads), the parser's when `pos` is on the line being read.
    enum class LoopNote { OnThisLine, Always };
    /// The
    /// same message at the same place again (a later loop pass, a file
    /// included twice) is counted on the first one, not printed again.
    void report(Severity severity, Pos pos, std::string message, LoopNote noted = LoopNote::OnThisLine) {
        if (stopped_) return;
        if (severity == Severity::Warning) {
            // Warnings do not stop parsing, so a hostile file could make millions.
            if (warnings_ >= limits_.maxWarnings) {
                if (droppedWarnings_++ == 0) firstDroppedWarning_ = pos;
                return;
            }
            ++warnings_;
        } else {
            ++errors_;
        }
        message += instanceNote_;
        std::string place = std::to_string(pos.file) + ':' + std::to_string(pos.line) + ':' +
                            std::to_string(pos.column) + (severity == Severity::Error ? "e" : "w") + message;
        if (auto it = firstAtPlace_.find(place); it != firstAtPlace_.end()) {
            ++repeats_[it->second].count;
        } else {
            const bool onThisLine = pos.seq != 0 && pos.seq == tokens_.pos.seq;
            const std::string note =
                noted == LoopNote::Always || onThisLine ? expander_.loopNote() : std::string();
            const bool inLoop = !note.empty();
            message += note;
            firstAtPlace_.emplace(std::move(place), diagnostics_.size());
            push({{expander_.fileName(pos.file), pos.line, pos.column},
                  severity,
                  std::move(message),
                  pos.length},
                 pos, inLoop);
        }
        if (severity == Severity::Error && errors_ >= limits_.maxErrors) {
            push({{expander_.fileName(pos.file), pos.line, pos.column},
                  Severity::Error,
                  "too many errors (" + std::to_string(errors_) + "); parsing stopped here"},
                 pos);
            stopped_ = true;
        }
    }
    void push(Diagnostic diagnostic, Pos pos, bool inLoop = false) {
        diagnostics_.push_back(std::move(diagnostic));
        order_.push_back(pos);
        repeats_.push_back({0, inLoop});
    }
    void error(Pos pos, std::string message) { report(Severity::Error, pos, std::move(message)); }
    void warning(Pos pos, std::string message) { report(Severity::Warning, pos, std::move(message)); }

    ParseResult finish() {
        if (droppedWarnings_ > 0) {
            push({{expander_.fileName(firstDroppedWarning_.file), firstDroppedWarning_.line,
                   firstDroppedWarning_.column},
                  Severity::Warning,
                  std::to_string(droppedWarnings_) + " more warnings from here on are not shown"},
                 firstDroppedWarning_);
        }
        for (std::size_t i = 0; i < diagnostics_.size(); ++i) {
            const Repeats& r = repeats_[i];
            if (r.count == 0) continue;
            const std::string n = std::to_string(r.count);
            diagnostics_[i].message +=
                r.inLoop ? " (and in " + n + (r.count == 1 ? " more pass)" : " more passes)")
                         : " (and " + n + (r.count == 1 ? " more time)" : " more times)");
        }
        // Duplicate-key warnings of out-of-order tracks are found at the end;
        // reading order, not line numbers, since loops read lines again.
        std::vector<std::size_t> index(diagnostics_.size());
        std::iota(index.begin(), index.end(), std::size_t{0});
        std::stable_sort(index.begin(), index.end(), [&](std::size_t a, std::size_t b) {
            const Pos& p = order_[a];
            const Pos& q = order_[b];
            return p.seq != q.seq ? p.seq < q.seq : p.column < q.column;
        });
        ParseResult result;
        result.diagnostics.reserve(index.size());
        for (std::size_t i : index) result.diagnostics.push_back(std::move(diagnostics_[i]));
        result.files = expander_.files();
        result.linesRead = expander_.linesRead();
        result.linesInFiles = expander_.linesInFiles();
        if (errors_ == 0) result.scene = std::move(scene_);
        return result;
    }

    // Tokens of the current line
    int argCount() const { return tokens_.count - 1; }
    std::string_view commandText() const { return tokens_.tokens[0].text; }
    Pos at(int column) const {
        Pos p = tokens_.pos;
        p.column = column;
        return p;
    }
    /// Where token i of the line is, with its written extent (so a diagnostic there covers it).
    /// A token past the stored ones (a line longer than kMaxStoredTokens) is
    /// reported at the last stored one: never read past the array.
    Pos tokenPos(int i) const {
        const LogicalToken& token = storedToken(i);
        Pos p = at(token.column);
        p.length = static_cast<int>(token.written.size());
        return p;
    }
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

    void parseLine() {
        const std::string_view head = commandText();
        if (!head.starts_with('/')) {
            std::string message = "expected a command starting with '/', got " + quoteToken(head);
            if (head.size() <= kMaxSuggestLength) {
                const std::string slashed = "/" + std::string(head);
                if (findCommand(slashed)) message += " (did you mean '" + slashed + "'?)";
            }
            error(commandPos(), noteCharacters(std::move(message), head, commandPos()));
            return;
        }
        if (building_) return parseModelLine(head);
        // The Source group never arrives here: the expander runs those lines.
        if (const CommandSpec* c = findCommand(head); c && c->group != CommandGroup::Source) {
            if (index_) index_->noteCommand(head, sourceLoc(commandPos()));
            dispatch(c->id);
            return;
        }
        if (const TypeBook* type = typeOfCommand(head)) {
            if (index_) index_->noteCommand(head, sourceLoc(commandPos()));
            return parseObject(ObjectKind::Model, type);
        }
        unknownCommand(head);
    }

    void unknownCommand(std::string_view head) {
        std::string message = "unknown command " + quoteToken(head);
        if (const std::string_view guess = suggestCommand(head); !guess.empty()) {
            message += " (did you mean '" + std::string(guess) + "'?)";
        }
        error(commandPos(), noteCharacters(std::move(message), head, commandPos()));
    }

    void dispatch(CommandId command) {
        using enum CommandId;
        switch (command) {
            case Camera:
                return parseCamera();
            case AmbLight:
                return parseAmbLight();
            case PointLight:
                return parseLocalLight(LocalLightKind::Point);
            case SpotLight:
                return parseLocalLight(LocalLightKind::Spot);
            case DirLight:
                return parseDirLight();
            case Background:
                return parseBackground();
            case Material:
                return parseMaterial();
            case Sphere:
                return parseObject(ObjectKind::Sphere);
            case Cylinder:
                return parseObject(ObjectKind::Cylinder);
            case Box:
                return parseObject(ObjectKind::Box);
            case Paint:
                return parsePaint();
            case Robot:
                return parseObject(ObjectKind::Model, &types_.at("robot"));
            case Human:
                return parseObject(ObjectKind::Model, &types_.at("human"));
            case Anim:
                return parseAnim();
            case Key:
                return parseKey();
            case Interp:
                return parseInterp();
            case Fps:
                return parseFps();
            case LookAt:
                return parseLookAt();
            case Attach:
                return parseAttach();
            case Checker:
                return parseChecker();
            case Caption:
                return parseCaption();
            case NoShadow:
                return parseNoShadow();
            case Model:
                return openModel();
            case Part:
                error(commandPos(), "'/part' stands only inside a '/model' block");
                return;
            case Drive:
                return parseDrive();
            case Let:
            case Repeat:
            case End:
            case Include:
                return;  // run by the SourceExpander
        }
    }

    /// Checks the argument count against the allowed ones ("3, 6 or 9"),
    /// not counting `optionArgs` arguments of options the command found.
    bool expectArgs(std::initializer_list<int> allowed, int optionArgs = 0) {
        const int n = argCount() - optionArgs;
        if (std::find(allowed.begin(), allowed.end(), n) != allowed.end()) return true;
        std::string list;
        std::size_t i = 0;
        for (int a : allowed) {
            if (i > 0) list += i + 1 == allowed.size() ? " or " : ", ";
            list += std::to_string(a);
            ++i;
        }
        const bool plural = allowed.size() > 1 || *allowed.begin() != 1;
        // A no-break space glues two arguments into one, so the count is the first thing wrong.
        error(commandPos(),
              noteCharacters(quoteToken(commandText()) + " takes " + list +
                                 (plural ? " arguments" : " argument") + ", got " + std::to_string(n),
                             commandLine(), commandPos()));
        return false;
    }

    // Argument readers: on a problem they report it, clear `ok` and return a harmless value.
    double number(int i, bool& ok) {
        const LogicalToken& token = argToken(i);
        if (token.form == TokenForm::Failed) {
            ok = false;
            return 0;
        }
        if (token.form == TokenForm::Expression) {
            // Scene values are single precision, as for a number written out (SPEC 7).
            if (std::fabs(token.value) <= kMaxNumberMagnitude) return token.value;
            error(argPos(i), "the value " + std::string(token.text) +
                                 " of the expression is out of range (the largest magnitude is 3.4e38)");
            ok = false;
            return 0;
        }
        const ParsedNumber n = parseNumber(token.text);
        if (n.status == NumberStatus::Ok) return n.value;
        if (secondsValue(token.text)) {
            error(argPos(i), "a time in seconds (" + quoteToken(token.written) +
                                 ") stands only where a key time does; here a number is expected");
        } else {
            error(argPos(i), noteCharacters(numberErrorMessage(token.text, n.status), token.text, argPos(i)));
        }
        ok = false;
        return 0;
    }

    /// The number of seconds in `2.5s` (an expression `(…)s` arrives so too), if `text` is one.
    static std::optional<double> secondsValue(std::string_view text) {
        if (text.size() < 2 || text.back() != 's') return std::nullopt;
        const ParsedNumber n = parseNumber(text.substr(0, text.size() - 1));
        if (n.status != NumberStatus::Ok) return std::nullopt;
        return n.value;
    }

    /// A key time (SPEC 10.4): a number of frames >= 0, fractions allowed, or
    /// seconds. Seconds are checked against the frame limit once `/fps` is known.
    KeyTime keyTime(int i, bool& ok) {
        KeyTime time;
        if (argToken(i).form == TokenForm::Word) {
            if (const std::optional<double> seconds = secondsValue(arg(i))) time = {*seconds, true};
        }
        bool good = true;
        if (!time.seconds) time.value = number(i, good);
        if (good && time.value < 0) {
            error(argPos(i), "a key time must be >= 0, got " + printable(arg(i)));
            good = false;
        } else if (good && !time.seconds && time.value > limits_.maxKeyFrame) {
            error(argPos(i), "a key time must be at most " + std::to_string(limits_.maxKeyFrame) +
                                 " frames, got " + printable(arg(i)));
            good = false;
        }
        ok = ok && good;
        if (time.value == 0) time.value = 0;  // -0 is 0, as for the other numbers
        return good ? time : KeyTime{};
    }

    float real(int i, bool& ok) { return static_cast<float>(number(i, ok)); }

    float positive(int i, std::string_view what, bool& ok) {
        bool good = true;
        const float v = real(i, good);
        // Checked after rounding to float: 1e-50 is > 0 as a double but 0 as a float.
        if (good && !(v > 0)) {
            error(argPos(i), std::string(what) + " must be > 0, got " + printable(arg(i)));
            good = false;
        }
        ok = ok && good;
        return good ? v : 1.0f;
    }

    float nonNegative(int i, std::string_view what, bool& ok) {
        bool good = true;
        const float v = real(i, good);
        if (good && v < 0) {
            error(argPos(i), std::string(what) + " must be >= 0, got " + printable(arg(i)));
            good = false;
        }
        ok = ok && good;
        return good ? v : 0.0f;
    }

    /// A whole number in [lo, hi]; "1e3" and "-0" count as whole.
    int whole(int i, std::string_view what, int lo, int hi, bool& ok) {
        bool good = true;
        double v = number(i, good);
        // SPEC 9.4: an expression within 1e-6 of a whole number gives that number.
        if (good && argToken(i).form == TokenForm::Expression) v = nearWhole(v).value_or(v);
        if (good && (v != std::floor(v) || v < lo || v > hi)) {
            error(argPos(i), std::string(what) + " must be a whole number from " + std::to_string(lo) +
                                 " to " + std::to_string(hi) + ", got " + printable(arg(i)));
            good = false;
        }
        ok = ok && good;
        return good ? static_cast<int>(v) : lo;
    }

    Vec3 vec3(int first, bool& ok) { return {real(first, ok), real(first + 1, ok), real(first + 2, ok)}; }

    Pose pose(int first, bool withRotation, bool& ok) {
        Pose p;
        p.position = vec3(first, ok);
        if (withRotation) p.rotation = vec3(first + 3, ok);
        return p;
    }

    Color8 color(int first, bool& ok) {
        static constexpr std::array<std::string_view, 3> kWhat = {"red", "green", "blue"};
        std::array<std::uint8_t, 3> c{};
        for (int k = 0; k < 3; ++k) {
            c[static_cast<std::size_t>(k)] =
                static_cast<std::uint8_t>(whole(first + k, kWhat[static_cast<std::size_t>(k)], 0, 255, ok));
        }
        return {c[0], c[1], c[2]};
    }

    /// A name for a new object: valid and not yet used.
    bool newName(int i) {
        if (failed(i)) return false;
        const std::string_view name = arg(i);
        if (!isValidName(name)) {
            error(argPos(i), noteCharacters("invalid name " + quoteToken(name) +
                                                " (expected a letter or '_', then letters, digits or '_')",
                                            name, argPos(i)));
            return false;
        }
        if (name == kCameraName) {
            error(argPos(i), "'camera' is the name of the scene camera; an object cannot take it");
            return false;
        }
        std::optional<std::pair<Pos, std::uint32_t>> first;  // where, and its loop note
        if (auto it = names_.find(name); it != names_.end())
            first = {books_[it->second].defined, books_[it->second].loopNote};
        if (auto it = lightNames_.find(name); it != lightNames_.end())
            first = {lightBooks_[it->second].defined, lightBooks_[it->second].loopNote};
        if (first) {
            error(argPos(i), "duplicate name " + quoteToken(name) + " (first defined at " +
                                 posText(first->first) +
                                 (first->second == 0 ? "" : " " + loopNotes_[first->second - 1]) + ")");
            return false;
        }
        return true;
    }

    /// The named light `name`, if it is one (SPEC 10.2).
    std::optional<int> lightNamed(std::string_view name) const {
        auto it = lightNames_.find(name);
        if (it == lightNames_.end()) return std::nullopt;
        return static_cast<int>(it->second);
    }

    /// Tells the symbol index that `name` at `pos` names the light `light`.
    void noteLightUse(int light, Pos pos, std::string_view name) {
        if (index_)
            index_->uses.push_back(
                {static_cast<std::size_t>(light), span(pos, name), std::string(commandText()), true});
    }

    /// "the light 'lamp'" or "the ambient light 'sky'", for messages.
    std::string lightText(int light) const {
        const LightMotion& l = scene_.lightMotions[static_cast<std::size_t>(light)];
        return std::string(l.ambient ? "the ambient light " : "the light ") + quoteToken(l.name);
    }

    /// Looks up an existing object by name; `token` is the whole argument, for the message;
    /// `cameraToo`: the command also takes `camera`, so it is a suggestion too ("Camera").
    std::optional<std::size_t> existing(std::string_view name, std::string_view token, Pos pos,
                                        bool cameraToo = false) {
        if (!isValidName(name)) {
            error(pos,
                  noteCharacters("invalid target " + quoteToken(token) + " (expected a name or name.part)",
                                 token, pos));
            return std::nullopt;
        }
        auto it = names_.find(name);
        if (it == names_.end()) {
            std::string message = "unknown name " + quoteToken(name);
            if (const std::string_view guess = suggestName(name, cameraToo); !guess.empty()) {
                message += " (did you mean '" + std::string(guess) + "'?)";
            }
            error(pos, std::move(message));
            return std::nullopt;
        }
        if (index_) index_->uses.push_back({it->second, span(pos, name), std::string(commandText())});
        return it->second;
    }

    /// The existing name closest to a mistyped one, in file order (then
    /// `camera` if `cameraToo`), within a total work budget for the whole file.
    std::string_view suggestName(std::string_view name, bool cameraToo) {
        ClosestWord closest(name);
        for (const SceneObject& o : scene_.objects) {
            if (nameSuggestWork_ >= kMaxNameSuggestWork) break;
            nameSuggestWork_ += closest.consider(o.name);
        }
        for (const LightMotion& l : scene_.lightMotions) {
            if (nameSuggestWork_ >= kMaxNameSuggestWork) break;
            nameSuggestWork_ += closest.consider(l.name);
        }
        if (cameraToo) closest.consider(kCameraName);
        return closest.best();
    }

    /// "body, head, lhand or rhand": the parts of a model, for messages.
    static std::string partList(const ModelType& model) {
        std::string list;
        for (std::size_t k = 0; k < model.parts.size(); ++k) {
            if (k > 0) list += k + 1 == model.parts.size() ? " or " : ", ";
            list += model.parts[k].name;
        }
        return list;
    }

    /// Checks that the object is a model and `part` one of its parts.
    std::optional<int> partOf(std::size_t object, std::string_view part, Pos pos) {
        const SceneObject& o = scene_.objects[object];
        if (!o.model) {
            error(pos, quoteToken(commandText()) + " on a part of a primitive: " + quoteToken(o.name) +
                           " is a " + std::string(objectKindName(o.kind)) + "; only models have parts");
            return std::nullopt;
        }
        const int index = o.model->partIndex(part);
        if (index < 0) {
            const std::string_view guess = suggestPart(part, *o.model);
            error(pos, noteCharacters("unknown part " + quoteToken(part) +
                                          (guess.empty() ? " (expected " + partList(*o.model) + ")"
                                                         : " (did you mean '" + std::string(guess) + "'?)"),
                                      part, pos));
            return std::nullopt;
        }
        return index;
    }

    /// Checks that `shape` is a shape on part `part` of the object's model.
    std::optional<int> shapeOf(std::size_t object, int part, std::string_view shape, Pos pos) {
        const ModelType& model = *scene_.objects[object].model;
        const int index = model.shapeIndex(part, shape);
        if (index >= 0) return index;
        std::string list;
        ClosestWord closest(shape);
        for (const ModelShape& s : model.shapes) {
            if (s.part != part) continue;
            list += (list.empty() ? "" : ", ") + s.name;
            closest.consider(s.name);
        }
        const std::string& partName = model.parts[std::size_t(part)].name;
        error(pos, noteCharacters(
                       "unknown shape " + quoteToken(shape) + " on the part " + quoteToken(partName) +
                           " of '" + model.name + "'" +
                           (!closest.best().empty() ? " (did you mean '" + std::string(closest.best()) + "'?)"
                            : list.empty()          ? " (it has no shapes)"
                                                    : " (expected " + list + ")"),
                       shape, pos));
        return std::nullopt;
    }

    /// Resolves `name` or `name.part` in argument i, or `camera` or a named
    /// light when the command takes them.
    std::optional<Target> target(int i, CameraTarget cameraUse = CameraTarget::Refused,
                                 LightTarget lightUse = LightTarget::Refused,
                                 ShapeTarget shapeUse = ShapeTarget::Refused) {
        if (failed(i)) return std::nullopt;
        const std::string_view text = arg(i);
        const Pos pos = argPos(i);
        const std::size_t dot = text.find('.');
        if (const std::optional<int> light = lightNamed(text.substr(0, dot))) {
            noteLightUse(*light, pos, text.substr(0, dot));
            if (lightUse == LightTarget::Refused) {
                error(pos, quoteToken(commandText()) + " does not apply to lights: " +
                               quoteToken(text.substr(0, dot)) + " is a light");
                return std::nullopt;
            }
            if (dot != std::string_view::npos) {
                Pos partPos = pos;
                partPos.column += static_cast<int>(dot) + 1;
                error(partPos, "a light has no parts");
                return std::nullopt;
            }
            Target t;
            t.light = *light;
            return t;
        }
        if (text.substr(0, dot) == kCameraName) {
            if (cameraUse == CameraTarget::Refused) {
                error(pos, quoteToken(commandText()) + " does not apply to the camera");
                return std::nullopt;
            }
            if (dot != std::string_view::npos) {
                Pos partPos = pos;  // the part itself, just after the dot
                partPos.column += static_cast<int>(dot) + 1;
                error(partPos, "the camera has no parts");
                return std::nullopt;
            }
            return Target{0, -1, true};
        }
        const std::optional<std::size_t> object =
            existing(text.substr(0, dot), text, pos, cameraUse != CameraTarget::Refused);
        if (!object) return std::nullopt;
        if (dot == std::string_view::npos) return Target{*object, -1};
        // Point at the part itself, just after the dot (of the token as written: "r{i}.head").
        const std::size_t writtenDot = argToken(i).written.find('.');
        Pos partPos = pos;
        partPos.column += static_cast<int>(writtenDot == std::string_view::npos ? dot : writtenDot) + 1;
        const std::string_view rest = text.substr(dot + 1);
        const std::size_t shapeDot = rest.find('.');
        const std::optional<int> part = partOf(*object, rest.substr(0, shapeDot), partPos);
        if (!part) return std::nullopt;
        if (shapeDot == std::string_view::npos) return Target{*object, *part};
        Pos shapePos = partPos;
        shapePos.column += static_cast<int>(shapeDot) + 1;
        shapePos.length = static_cast<int>(rest.size() - shapeDot - 1);
        const std::optional<int> shape = shapeOf(*object, *part, rest.substr(shapeDot + 1), shapePos);
        if (!shape) return std::nullopt;
        if (shapeUse == ShapeTarget::Refused) {
            error(shapePos,
                  quoteToken(commandText()) + " does not apply to a shape: " + quoteToken(text) +
                      " is a shape, which takes looks and colour or visible keys only (its part is " +
                      quoteToken(text.substr(0, dot + 1 + shapeDot)) + ")");
            return std::nullopt;
        }
        Target t{*object, *part};
        t.shape = *shape;
        return t;
    }

    std::string targetName(Target t) const {
        if (t.camera) return std::string(kCameraName);
        if (t.light >= 0) return scene_.lightMotions[static_cast<std::size_t>(t.light)].name;
        const SceneObject& o = scene_.objects[t.object];
        std::string s = o.name;
        if (t.part >= 0) s += "." + o.model->parts[std::size_t(t.part)].name;
        if (t.shape >= 0) s += "." + o.model->shapes[std::size_t(t.shape)].name;
        return s;
    }

    /// The track of `t`'s pose, or of one of its properties (SPEC 10.3).
    Track& trackOf(Target t, TrackProperty property = std::nullopt) {
        if (property == KeyProperty::Zoom) return scene_.camera.zoom;
        if (property == KeyProperty::Intensity) return lightMotion(t).intensity;
        if (property == KeyProperty::Colour) return scene_.colourTracks[targetTrackIndex(t, *property)].track;
        if (property == KeyProperty::Visible)
            return scene_.visibilityTracks[targetTrackIndex(t, *property)].track;
        if (t.camera) return scene_.camera.track;
        if (t.light >= 0) return lightMotion(t).track;
        SceneObject& o = scene_.objects[t.object];
        return t.part < 0 ? o.track : o.partTracks[static_cast<std::size_t>(t.part)];
    }
    LightMotion& lightMotion(Target t) { return scene_.lightMotions[static_cast<std::size_t>(t.light)]; }
    LightBook& lightBook(Target t) { return lightBooks_[static_cast<std::size_t>(t.light)]; }

    /// The index of an object's or part's colour track (SPEC 10.3) or visibility
    /// track (10.7) in its list, made on its first key.
    std::size_t targetTrackIndex(Target t, KeyProperty property) {
        const bool visible = property == KeyProperty::Visible;
        auto [it, added] = (visible ? visibilityTrackIndex_ : colourTrackIndex_).try_emplace(slotOf(t), 0);
        if (added) {
            std::vector<TargetTrack>& tracks = visible ? scene_.visibilityTracks : scene_.colourTracks;
            it->second = tracks.size();
            Track track;
            if (visible) track.interpolation = Interpolation::Step;  // always a step (SPEC 10.7)
            tracks.push_back({FrameRef{static_cast<std::uint32_t>(t.object), t.part}, t.shape, track});
            (visible ? visibilityTrackBooks_ : colourTrackBooks_).push_back(-1);
        }
        return it->second;
    }

    // Commands
    /// Reports a repeated single-use command; remembers the first one.
    bool firstOnly(std::optional<Pos>& seen) {
        if (seen) {
            error(commandPos(),
                  "second " + quoteToken(commandText()) + " (the first is at " + posText(*seen) + ")");
            return false;
        }
        seen = commandPos();
        return true;
    }

    void parseCamera() {
        if (!firstOnly(cameraSeen_) || !expectArgs({3, 6, 9})) return;
        bool ok = true;
        CameraDesc camera;
        camera.width = whole(0, "image width", 1, limits_.maxImageSide, ok);
        camera.height = whole(1, "image height", 1, limits_.maxImageSide, ok);
        {
            bool good = true;
            camera.distance = number(2, good);
            if (good && !(camera.distance > 0)) {
                error(argPos(2), "screen distance must be > 0, got " + printable(arg(2)));
                good = false;
            }
            ok = ok && good;
        }
        if (argCount() >= 6) camera.pose = pose(3, argCount() == 9, ok);
        // Keys, /look_at and /attach of the camera may come before /camera.
        camera.track = std::move(scene_.camera.track);
        camera.zoom = std::move(scene_.camera.zoom);
        camera.attachedTo = scene_.camera.attachedTo;
        camera.lookAt = scene_.camera.lookAt;
        if (!ok) return;
        const long long pixels = static_cast<long long>(camera.width) * camera.height;
        if (pixels > limits_.maxImagePixels) {
            error(argPos(0), "image of " + std::to_string(camera.width) + "x" +
                                 std::to_string(camera.height) + " = " + std::to_string(pixels) +
                                 " pixels is larger than the limit of " +
                                 std::to_string(limits_.maxImagePixels) + " pixels");
            return;
        }
        scene_.camera = camera;
    }

    /// SPEC 7: at most maxLights light commands of every kind together.
    bool lightAllowed() {
        if (++lightLines_ <= limits_.maxLights) return true;
        error(commandPos(), "too many lights: at most " + std::to_string(limits_.maxLights) +
                                " allowed (ambient, directional, point and spot together)");
        return false;
    }

    void parseAmbLight() {
        if (!expectArgs({1, 3}) || !lightAllowed()) return;
        bool ok = true;
        const float i = nonNegative(0, "ambient intensity", ok);
        LightOptions options;
        if (!lightOptions(1, {LightOption::Name}, options) || !ok) return;
        // Named or not, every ambient light as written adds to one sum.
        const float sum = writtenAmbient_ + i;
        if (!std::isfinite(sum)) {
            error(argPos(0), "total ambient intensity is out of range");
            return;
        }
        writtenAmbient_ = sum;
        if (options.nameArg >= 0) {
            scene_.namedAmbients.push_back(
                {i, static_cast<std::uint32_t>(registerLight(options.nameArg, true))});
            return;
        }
        scene_.ambient += i;
    }

    /// A light's direction (arguments first..first+2): not 0 0 0, and
    /// normalisable in float.
    Vec3 lightDirection(int first, bool& ok) {
        bool good = true;
        const Vec3 d = vec3(first, good);
        if (good && d.x == 0 && d.y == 0 && d.z == 0) {
            error(argPos(first), "light direction must not be 0 0 0");
            good = false;
        }
        // The renderer normalises in float: the squared length must neither vanish nor overflow.
        const float lengthSquared = dot(d, d);
        if (good && (!(lengthSquared > 0) || !std::isfinite(lengthSquared))) {
            error(argPos(first),
                  "light direction cannot be normalised (its length is too close to 0 or too large)");
            good = false;
        }
        ok = ok && good;
        return d;
    }

    /// The options a light command may end with: a word and its numbers.
    struct LightOptions {
        Fade fade;
        SoftShadow shadow;
        float tightness = 0;
        int nameArg = -1;  ///< the argument holding `name`'s word, -1 if unnamed
    };

    /// Reads the options after argument `first` (docs/scene-language.md,
    /// "Point and spot lights"); each of `allowed` at most once.
    bool lightOptions(int first, std::initializer_list<LightOption> allowed, LightOptions& out) {
        const std::span<const LightOptionSpec> kSpecs = f2::lightOptions();
        bool ok = true;
        std::vector<LightOption> seen;
        for (int i = first; i < argCount();) {
            const LightOptionSpec* spec = nullptr;
            for (const LightOptionSpec& candidate : kSpecs)
                if (candidate.word == arg(i) &&
                    std::find(allowed.begin(), allowed.end(), candidate.option) != allowed.end())
                    spec = &candidate;
            if (!spec) {
                std::string expected;
                for (LightOption o : allowed) {
                    if (!expected.empty()) expected += o == *(allowed.end() - 1) ? " or " : ", ";
                    expected += "'" + std::string(kSpecs[static_cast<std::size_t>(o)].word) + "'";
                }
                error(argPos(i), "unknown option " + quoteToken(arg(i)) + " of " + quoteToken(commandText()) +
                                     " (expected " + expected + ")");
                return false;
            }
            if (std::find(seen.begin(), seen.end(), spec->option) != seen.end()) {
                error(argPos(i), "second " + quoteToken(arg(i)) + " option");
                return false;
            }
            seen.push_back(spec->option);
            if (i + spec->numbers >= argCount()) {
                error(argPos(i), quoteToken(arg(i)) + " takes " + std::string(spec->what));
                return false;
            }
            switch (spec->option) {
                case LightOption::Fade:
                    out.fade.distance = positive(i + 1, "fade distance", ok);
                    out.fade.power = positive(i + 2, "fade power", ok);
                    break;
                case LightOption::Size:
                case LightOption::Angle: {
                    const bool angle = spec->option == LightOption::Angle;
                    bool good = true;
                    out.shadow.size = positive(i + 1, angle ? "angular radius" : "light diameter", good);
                    if (good && angle && out.shadow.size > kMaxSunRadius) {
                        error(argPos(i + 1),
                              "angular radius must be at most 45 degrees, got " + printable(arg(i + 1)));
                        good = false;
                    }
                    out.shadow.samplesPerSide =
                        whole(i + 2, "samples per side", 2, kMaxShadowSamplesPerSide, good);
                    ok = ok && good;
                    break;
                }
                case LightOption::Tightness:
                    out.tightness = nonNegative(i + 1, "tightness", ok);
                    break;
                case LightOption::Name:
                    if (newName(i + 1))
                        out.nameArg = i + 1;
                    else
                        ok = false;
                    break;
            }
            i += 1 + spec->numbers;
        }
        return ok;
    }

    /// A light command's `fixed` arguments are there (options may follow) and
    /// the light limit is not reached.
    bool lightArgsAllowed(int fixed) {
        if (argCount() < fixed) {
            expectArgs({fixed});
            return false;
        }
        if (argCount() > kMostLightArgs) {
            error(commandPos(), quoteToken(commandText()) + " takes at most " +
                                    std::to_string(kMostLightArgs) + " arguments with its options, got " +
                                    std::to_string(argCount()));
            return false;
        }
        return lightAllowed();
    }

    /// The most arguments of a light command: /spot_light's 9 and its four
    /// options (tightness k, fade d p, size s n, name n). Every one is stored (kMaxStoredTokens).
    static constexpr int kMostLightArgs = 9 + 2 + 3 + 3 + 2;
    static_assert(kMostLightArgs + 1 <= kMaxStoredTokens);

    /// The largest angular radius of a soft sun (degrees): wider is no longer a sun.
    static constexpr float kMaxSunRadius = 45.0f;

    void parseDirLight() {
        if (!lightArgsAllowed(4)) return;
        bool ok = true;
        DirectionalLight light;
        light.intensity = nonNegative(0, "light intensity", ok);
        light.direction = lightDirection(1, ok);
        LightOptions options;
        if (!lightOptions(4, {LightOption::Angle, LightOption::Name}, options) || !ok) return;
        light.sun = options.shadow;
        if (options.nameArg >= 0) light.motion = registerLight(options.nameArg, false);
        scene_.lights.push_back(light);
    }

    /// `/point_light <i> <x> <y> <z> [fade D P] [size S N]` and
    /// `/spot_light <i> <x> <y> <z> <dx> <dy> <dz> <radius> <falloff> [tightness T] [fade D P] [size S N]`
    void parseLocalLight(LocalLightKind kind) {
        const bool spot = kind == LocalLightKind::Spot;
        const int fixed = spot ? 9 : 4;
        if (!lightArgsAllowed(fixed)) return;
        bool ok = true;
        LocalLight light;
        light.kind = kind;
        light.intensity = nonNegative(0, "light intensity", ok);
        light.position = vec3(1, ok);
        if (spot) {
            light.direction = lightDirection(4, ok);
            bool good = true;
            light.radius = nonNegative(7, "spot radius", good);
            light.falloff = nonNegative(8, "spot falloff", good);
            if (good && light.falloff > 90) {
                error(argPos(8), "spot falloff must be at most 90 degrees, got " + printable(arg(8)));
                good = false;
            }
            if (good && light.radius > light.falloff) {
                error(argPos(7), "spot radius must be at most its falloff (" + printable(arg(8)) + "), got " +
                                     printable(arg(7)));
                good = false;
            }
            ok = ok && good;
        }
        LightOptions options;
        const bool optionsOk =
            spot ? lightOptions(
                       fixed,
                       {LightOption::Tightness, LightOption::Fade, LightOption::Size, LightOption::Name},
                       options)
                 : lightOptions(fixed, {LightOption::Fade, LightOption::Size, LightOption::Name}, options);
        if (!optionsOk || !ok) return;
        light.tightness = options.tightness;
        light.fade = options.fade;
        light.area = options.shadow;
        if (options.nameArg >= 0) light.motion = registerLight(options.nameArg, false);
        scene_.localLights.push_back(light);
    }

    /// Makes the light named by argument `nameArg` (valid and new) a target of
    /// `/key`, `/interp` and `/attach` (SPEC 10.2); returns its lightMotions index.
    std::int32_t registerLight(int nameArg, bool ambient) {
        const auto index = static_cast<std::int32_t>(scene_.lightMotions.size());
        LightMotion motion;
        motion.name = std::string(arg(nameArg));
        motion.ambient = ambient;
        lightNames_.emplace(motion.name, scene_.lightMotions.size());
        scene_.lightMotions.push_back(std::move(motion));
        lightBooks_.push_back({argPos(nameArg), definitionLoopNote(), -1, -1, std::nullopt, std::nullopt});
        if (index_) {
            index_->lights.push_back({std::string(arg(nameArg)), std::string(commandText()),
                                      span(argPos(nameArg), arg(nameArg)), sourceLoc(commandPos())});
        }
        return index;
    }

    void parseBackground() {
        if (!firstOnly(backgroundSeen_) || !expectArgs({3})) return;
        bool ok = true;
        const Color8 c = color(0, ok);
        if (ok) scene_.background = c;
    }

    void parseFps() {
        if (!firstOnly(fpsSeen_) || !expectArgs({1})) return;
        bool ok = true;
        const int fps = whole(0, "fps", 1, limits_.maxFps, ok);
        if (ok) scene_.fps = fps;
    }

    /// How many numbers give a primitive's size: 1 sphere, 2 cylinder, 3 box, 0 a model.
    static int sizeArgCount(ObjectKind kind) {
        return kind == ObjectKind::Sphere     ? 1
               : kind == ObjectKind::Cylinder ? 2
               : kind == ObjectKind::Box      ? 3
                                              : 0;
    }

    /// The size of a primitive from arguments first… (radius; radius and height; sides).
    Vec3 primitiveSize(ObjectKind kind, int first, bool& ok) {
        static constexpr std::array<std::string_view, 3> kBoxWhat = {"side sx", "side sy", "side sz"};
        static constexpr std::array<std::string_view, 2> kCylinderWhat = {"radius", "height"};
        Vec3 size;
        for (int k = 0; k < sizeArgCount(kind); ++k) {
            const std::string_view what = kind == ObjectKind::Box
                                              ? kBoxWhat[static_cast<std::size_t>(k)]
                                              : kCylinderWhat[static_cast<std::size_t>(k)];
            size[k] = positive(first + k, what, ok);
        }
        return size;
    }

    /// A primitive (`type` null) or an instance of a model type (SPEC 10.1),
    /// with its parameters' values after the pose (SPEC 10.6).
    void parseObject(ObjectKind kind, const TypeBook* type = nullptr) {
        const int sizeArgs = sizeArgCount(kind);
        const int withoutRotation = 1 + sizeArgs + 3;
        SceneObject object;
        object.kind = kind;
        if (type) makeInstance(object, type->type);
        // An instance's parameters start at the first word after its position.
        int options = argCount();
        if (type) {
            for (int i = withoutRotation; i < std::min(argCount(), kMaxStoredTokens - 1); ++i) {
                if (isWordArgument(i)) {
                    options = i;
                    break;
                }
            }
        }
        // After an error about the whole line, a valid new name is still
        // registered with its kind, so later lines that use it do not add
        // "unknown name" errors. The error count caps how far this goes past
        // the object limit.
        const bool countOk = expectArgs({withoutRotation, withoutRotation + 3}, argCount() - options);
        const bool roomOk = scene_.objects.size() < limits_.maxObjects;
        if (countOk && !roomOk) {
            error(commandPos(), "too many objects: at most " + std::to_string(limits_.maxObjects) +
                                    " allowed (a robot or human counts as one)");
        }
        if (!countOk || !roomOk) {
            if (argCount() >= 1 && isValidName(arg(0)) && !names_.contains(arg(0))) {
                addObject(std::move(object));
            }
            return;
        }

        bool ok = true;
        object.size = primitiveSize(kind, 1, ok);
        object.rest = pose(1 + sizeArgs, options == withoutRotation + 3, ok);
        const std::optional<std::vector<ModelParam>> params =
            type && options < argCount() ? instanceParams(*type->type, options) : std::nullopt;
        // A valid new name is registered even if other arguments are wrong, so
        // later lines that use it do not add "unknown name" errors.
        if (!newName(0)) return;
        ObjectLine line = objectLine();
        if (ok && params && !sameValues(*params, type->type->params)) {
            // The block read again with the instance's values; after an error in it, the type as defined.
            if (std::shared_ptr<const ModelType> own = readBlockFor(*type, *params, line))
                makeInstance(object, std::move(own));
        }
        addObject(std::move(object), std::move(line));
    }

    static bool sameValues(const std::vector<ModelParam>& a, const std::vector<ModelParam>& b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                          [](const ModelParam& x, const ModelParam& y) { return x.value == y.value; });
    }

    /// The loop values of the line being read ("in /repeat k = 0") as an index
    /// into loopNotes_ + 1, shared by the objects of one pass; 0 outside loops.
    std::uint32_t definitionLoopNote() {
        std::string note = expander_.loopNote();
        if (note.empty()) return 0;
        note = note.substr(2, note.size() - 3);  // " (in … )" -> "in …"
        if (loopNotes_.empty() || loopNotes_.back() != note) loopNotes_.push_back(std::move(note));
        return static_cast<std::uint32_t>(loopNotes_.size());
    }

    /// Adds the object named by argument 0, which is valid and new.
    void addObject(SceneObject object) { addObject(std::move(object), objectLine()); }
    void addObject(SceneObject object, ObjectLine line) {
        object.name = std::move(line.name);
        names_.emplace(object.name, scene_.objects.size());
        if (index_) index_->objects.push_back({object, line.nameSpan, sourceLoc(line.command)});
        books_.push_back({line.namePos, std::nullopt, line.loopNote});
        scene_.objects.push_back(std::move(object));
    }
    /// The creating command's line (its name in argument 0), as addObject needs it.
    ObjectLine objectLine() {
        return {std::string(arg(0)), argPos(0), commandPos(), span(argPos(0), arg(0)), definitionLoopNote()};
    }

    /// Warnings about a scene that parses but is almost certainly not what was
    /// meant. Only for a scene without errors: a rejected scene is never shown.
    void warnAboutTheWholeScene() {
        if (scene_.objects.empty()) {
            warning({1, 1}, "the scene has no objects: every frame shows only the background");
            return;
        }
        const auto keyedOn = [](const Track& t) {
            return std::any_of(t.keys.begin(), t.keys.end(),
                               [](const Key& k) { return k.pose.position.x > 0; });
        };
        const bool lit = scene_.ambient > 0 ||
                         std::any_of(scene_.namedAmbients.begin(), scene_.namedAmbients.end(),
                                     [](const AmbientLight& l) { return l.intensity > 0; }) ||
                         std::any_of(scene_.lightMotions.begin(), scene_.lightMotions.end(),
                                     [&](const LightMotion& l) { return keyedOn(l.intensity); }) ||
                         std::any_of(scene_.lights.begin(), scene_.lights.end(),
                                     [](const DirectionalLight& l) { return l.intensity > 0; }) ||
                         std::any_of(scene_.localLights.begin(), scene_.localLights.end(),
                                     [](const LocalLight& l) { return l.intensity > 0; });
        if (!lit) {
            warning(books_.front().defined,
                    "the scene has no light (no '/amb_light', '/dir_light', '/point_light' or "
                    "'/spot_light' with an intensity > 0): every object renders black");
        }
    }

    /// What a look command sets (SPEC 3, 10.1): a colour, which a shape painted
    /// in its model keeps unless the command names that shape, or the rest of
    /// the look, which reaches every shape of the target.
    enum class LookPart : bool { Colour, Other };

    /// The shapes' appearances a `/paint`-like command on `t` sets (SPEC 3, 10.1):
    /// a primitive's, a model's shape's, a part's shapes' or every shape's.
    template <class Set>
    void setAppearance(const Target& t, LookPart what, Set&& set) {
        SceneObject& o = scene_.objects[t.object];
        if (!o.model) return set(o.appearance[0]);
        if (t.shape >= 0) return set(o.appearance[std::size_t(t.shape)]);
        const std::vector<ModelShape>& shapes = o.model->shapes;
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            if (t.part >= 0 && shapes[k].part != t.part) continue;
            if (what == LookPart::Colour && shapes[k].ownColor) continue;  // painted in its model
            set(o.appearance[k]);
        }
    }

    /// Where a look command's target is: a shape of the model being read
    /// (SPEC 10.1, `part.shape`), else a target of the scene.
    struct LookTarget {
        std::optional<Target> scene;
        ModelShape* modelShape = nullptr;
        explicit operator bool() const { return scene || modelShape; }
    };
    LookTarget lookTarget(int i) {
        if (!building_)
            return {target(i, CameraTarget::Refused, LightTarget::Refused, ShapeTarget::Accepted)};
        const std::optional<int> shape = modelShapeArgument(i);
        return {std::nullopt, shape ? &building_->type->shapes[std::size_t(*shape)] : nullptr};
    }
    template <class Set>
    void setLook(const LookTarget& t, LookPart what, Set&& set) {
        if (t.modelShape) {
            set(t.modelShape->look);
            if (what == LookPart::Colour) t.modelShape->ownColor = true;
            return;
        }
        setAppearance(*t.scene, what, set);
    }

    void parsePaint() {
        if (!expectArgs({4})) return;
        bool ok = true;
        const LookTarget t = lookTarget(0);
        const Color8 c = color(1, ok);
        if (!t || !ok) return;
        setLook(t, LookPart::Colour, [&](Appearance& a) { a.color = c; });
    }

    void parseMaterial() {
        // `emit e` (SPEC 10.8) ends the line when it is there. Only a line of
        // 7 or 8 arguments can hold it (and only so long a line has its
        // tokens stored: kMaxStoredTokens).
        const int n = argCount();
        const bool emits = (n == 7 || n == 8) && isWordArgument(n - 2) && arg(n - 2) == kEmitWord;
        if (n == 6 && isWordArgument(5) && arg(5) == kEmitWord) {
            error(argPos(5), "'emit' takes a number (the emission e >= 0)");
            return;
        }
        if (!expectArgs({5, 6}, emits ? 2 : 0)) return;
        bool ok = true;
        const LookTarget t = lookTarget(0);
        Material m;
        m.ka = nonNegative(1, "ka", ok);
        m.kd = nonNegative(2, "kd", ok);
        m.ks = nonNegative(3, "ks", ok);
        m.n = positive(4, "n", ok);
        if (n - (emits ? 2 : 0) == 6) m.reflection = nonNegative(5, "reflection", ok);
        if (emits) m.emission = nonNegative(n - 1, "emission", ok);
        if (!t || !ok) return;
        setLook(t, LookPart::Other, [&](Appearance& a) { a.material = m; });
    }

    /// `/no_shadow <target>` (SPEC 10.8): the target casts no shadow.
    void parseNoShadow() {
        if (!expectArgs({1})) return;
        const std::optional<Target> t =
            target(0, CameraTarget::Refused, LightTarget::Refused, ShapeTarget::Accepted);
        if (!t) return;
        setAppearance(*t, LookPart::Other, [](Appearance& a) { a.castsShadow = false; });
    }

    /// `/checker <target> <r> <g> <b> <size>`: the second colour and cell size
    /// of a checker pattern (docs/rendering.md).
    void parseChecker() {
        if (!expectArgs({5})) return;
        bool ok = true;
        const LookTarget t = lookTarget(0);
        Checker checker;
        checker.color = color(1, ok);
        checker.size = positive(4, "cell size", ok);
        if (!t || !ok) return;
        // A chequered colour is a colour: a shape painted in its model keeps its own.
        setLook(t, LookPart::Colour, [&](Appearance& a) { a.checker = checker; });
    }

    // Models (SPEC 10.1)
    /// `/model <type>`: starts reading a block; its lines go to parseModelLine
    /// up to the `/end` the expander pairs with it.
    void openModel() {
        building_.emplace();
        building_->type = std::make_shared<ModelType>();
        building_->defined = commandPos();
        readModelHeader(*building_);
        // Errors from here on are in the block's lines ("no shapes" may follow from them).
        building_->errorsBefore = errors_;
    }

    /// The `/model` line itself: the type's name and parameters.
    void readModelHeader(ModelBuild& build) {
        // `/model <type> [<param> <default>]…` (SPEC 10.6): each default is
        // the parameter's value while the block is read here.
        if (argCount() == 0) {
            expectArgs({1});
            return;
        }
        // A parameter without its default is left out; the type is still defined.
        // (A line longer than the stored tokens is reported by modelParams.)
        if (argCount() % 2 == 0 && argCount() < kMaxStoredTokens) {
            error(argPos(argCount() - 1), "the parameter " + quoteToken(arg(argCount() - 1)) +
                                              " needs a default value: '/model <type> [<param> <default>]…'");
        }
        build.type->params = modelParams();
        if (failed(0)) return;
        const std::string_view name = arg(0);
        const Pos pos = argPos(0);
        if (!isValidName(name)) {
            error(pos, noteCharacters("invalid model type " + quoteToken(name) +
                                          " (expected a letter or '_', then letters, digits or '_')",
                                      name, pos));
            return;
        }
        const std::string slashed = "/" + std::string(name);
        if (const auto it = types_.find(name); it != types_.end()) {
            error(pos, it->second.defined ? "model type " + quoteToken(name) + " is already defined (at " +
                                                posText(*it->second.defined) + ")"
                                          : quoteToken(name) + " is a built-in model type ('" + slashed +
                                                "' makes one); choose another name");
            return;
        }
        if (findCommand(slashed) || name == kRootName || name == kCameraName) {
            error(pos,
                  quoteToken(name) + " cannot name a model type: " +
                      (findCommand(slashed) ? "'" + slashed + "' is a command" : "it is a reserved word"));
            return;
        }
        if (types_.size() >= std::size_t(kMaxModelTypes)) {
            error(pos, "too many model types: at most " + std::to_string(kMaxModelTypes) +
                           " allowed (the robot and the human count)");
            return;
        }
        build.type->name = std::string(name);
        build.namePos = pos;
        build.named = true;
        start_ = expander_.lastModelBlock();
        build.indexed.name = span(pos, name);
        build.indexed.command = sourceLoc(commandPos());
    }

    /// The `<param> <default>` pairs after a `/model`'s type (SPEC 10.6), each
    /// set as a variable of the block; a bad one is reported and left out.
    std::vector<ModelParam> modelParams() {
        std::vector<ModelParam> params;
        // Only so many tokens of a line are stored (kMaxStoredTokens): the rest is an error.
        if (argCount() >= kMaxStoredTokens) {
            error(commandPos(), "too many parameters on one '/model' line: at most " +
                                    std::to_string((kMaxStoredTokens - 2) / 2));
            return {};
        }
        for (int i = 1; i + 1 < argCount(); i += 2) {
            if (failed(i)) continue;
            const std::string_view name = arg(i);
            bool ok = true;
            const double value = real(i + 1, ok);
            if (!isValidName(name) || Variables::isPredefined(name)) {
                error(argPos(i),
                      noteCharacters(Variables::isPredefined(name)
                                         ? quoteToken(name) + " is a constant; a parameter cannot take "
                                                              "its name"
                                         : "invalid parameter name " + quoteToken(name) +
                                               " (expected a letter or '_', then letters, digits or "
                                               "'_')",
                                     name, argPos(i)));
                continue;
            }
            if (std::any_of(params.begin(), params.end(),
                            [&](const ModelParam& p) { return p.name == name; })) {
                error(argPos(i), "the parameter " + quoteToken(name) + " is given twice");
                continue;
            }
            if (!ok) continue;
            params.push_back({std::string(name), value});
            expander_.setVariable(name, value);
        }
        return params;
    }

    /// The instance's values of its type's parameters (SPEC 10.6): the option
    /// words from argument `first` on, any order, each once; nullopt after an error.
    std::optional<std::vector<ModelParam>> instanceParams(const ModelType& type, int first) {
        std::vector<ModelParam> values = type.params;
        std::vector<bool> given(values.size(), false);
        if (argCount() >= kMaxStoredTokens) {
            error(commandPos(), "too many arguments: an instance's line holds at most " +
                                    std::to_string(kMaxStoredTokens - 1) + " (its parameters included)");
            return std::nullopt;
        }
        bool ok = true;
        for (int i = first; i < argCount(); i += 2) {
            if (failed(i)) {
                ok = false;
                continue;
            }
            const std::string_view word = arg(i);
            const auto it = std::find_if(values.begin(), values.end(),
                                         [&](const ModelParam& p) { return p.name == word; });
            if (it == values.end()) {
                std::string names;
                for (std::size_t k = 0; k < type.params.size(); ++k)
                    names +=
                        (k > 0 ? (k + 1 == type.params.size() ? " and " : ", ") : "") + type.params[k].name;
                error(argPos(i), "unknown parameter " + quoteToken(word) + " of '" + type.name + "' (" +
                                     (names.empty() ? "it has no parameters" : "its parameters: " + names) +
                                     ")");
                ok = false;
                continue;
            }
            const std::size_t k = std::size_t(it - values.begin());
            if (given[k]) {
                error(argPos(i), "the parameter " + quoteToken(word) + " is given twice");
                ok = false;
                continue;
            }
            given[k] = true;
            if (i + 1 >= argCount()) {
                error(argPos(i), "the parameter " + quoteToken(word) + " needs a value");
                ok = false;
                continue;
            }
            it->value = real(i + 1, ok);
        }
        if (!ok) return std::nullopt;
        return values;
    }

    /// Reads `book`'s block again with an instance's parameter values (SPEC
    /// 10.6): the instance's own type, or null after an error in it.
    std::shared_ptr<const ModelType> readBlockFor(const TypeBook& book, const std::vector<ModelParam>& values,
                                                  const ObjectLine& line) {
        expander_.replayModelBlock(book.start);
        for (const ModelParam& p : values) expander_.setVariable(p.name, p.value);
        building_.emplace();
        ModelBuild& build = *building_;
        build.type = std::make_shared<ModelType>();
        build.type->name = book.type->name;
        build.type->params = values;
        build.defined = build.namePos = *book.defined;
        build.errorsBefore = errors_;
        build.named = true;
        build.readFor = book.type;
        const std::string outerNote = std::move(instanceNote_);
        instanceNote_ = " (in /" + book.type->name + " " + line.name + ")";
        std::shared_ptr<const ModelType> read = build.type;
        const std::size_t errorsBefore = errors_;
        while (!stopped_ && building_ && expander_.next(tokens_)) parseLine();
        instanceNote_ = outerNote;
        return errors_ == errorsBefore ? read : nullptr;
    }

    /// Part and shape names of a block read again for an instance must be its type's (SPEC 10.6).
    bool sameNames(const ModelType& a, const ModelType& b) {
        if (a.parts.size() != b.parts.size() || a.shapes.size() != b.shapes.size()) return false;
        for (std::size_t k = 0; k < a.parts.size(); ++k)
            if (a.parts[k].name != b.parts[k].name || a.parts[k].parent != b.parts[k].parent) return false;
        for (std::size_t k = 0; k < a.shapes.size(); ++k)
            if (a.shapes[k].name != b.shapes[k].name || a.shapes[k].part != b.shapes[k].part) return false;
        return true;
    }

    /// A line inside a `/model` block.
    void parseModelLine(std::string_view head) {
        ModelBuild& build = *building_;
        const CommandSpec* c = findCommand(head);
        if (c && c->id == CommandId::End) {
            if (build.nested > 0) {
                --build.nested;
                return;
            }
            return closeModel();
        }
        if (c && c->id == CommandId::Model) {
            error(commandPos(), "a '/model' cannot stand inside another (the block of " + modelText(build) +
                                    " is open until its '/end')");
            ++build.nested;
            return;
        }
        if (build.nested > 0) return;  // the lines of a refused block
        if (!c) return unknownCommand(head);
        using enum CommandId;
        switch (c->id) {
            case Part:
                return parsePart();
            case Sphere:
                return parseModelShape(ShapeKind::Sphere, ObjectKind::Sphere);
            case Cylinder:
                return parseModelShape(ShapeKind::Cylinder, ObjectKind::Cylinder);
            case Box:
                return parseModelShape(ShapeKind::Box, ObjectKind::Box);
            case Paint:
                return parsePaint();
            case Material:
                return parseMaterial();
            case Checker:
                return parseChecker();
            default:
                error(commandPos(), quoteToken(head) +
                                        " cannot stand inside a '/model' block (only /part, "
                                        "/sphere, /cylinder, /box, /paint, /material, /checker, "
                                        "/let, /repeat and /include; the block of " +
                                        modelText(build) + " ends with '/end')");
        }
    }

    static std::string modelText(const ModelBuild& build) {
        return build.named ? quoteToken(build.type->name) : std::string("the model");
    }

    /// `/part <part> <parent> <px> <py> <pz> [<rx> <ry> <rz>]`.
    void parsePart() {
        ModelType& type = *building_->type;
        if (!expectArgs({5, 8})) return;
        bool ok = true;
        ModelPart part;
        part.pivot = vec3(2, ok);
        const Vec3 rest = argCount() == 8 ? vec3(5, ok) : Vec3{};
        setRestRotation(part, rest);
        if (failed(0) || failed(1)) return;
        const std::string_view name = arg(0), parent = arg(1);
        if (!isValidName(name)) {
            error(argPos(0), noteCharacters("invalid part name " + quoteToken(name) +
                                                " (expected a letter or '_', then letters, digits or '_')",
                                            name, argPos(0)));
            return;
        }
        if (name == kRootName) {
            error(argPos(0),
                  "'root' is the model's own frame, the parent of its first parts; a part cannot "
                  "take the name");
            return;
        }
        if (type.partIndex(name) >= 0) {
            error(argPos(0), "duplicate part " + quoteToken(name) + " in " + modelText(*building_));
            return;
        }
        if (parent == kRootName) {
            part.parent = -1;
        } else if (const int index = type.partIndex(parent); index >= 0) {
            part.parent = index;
        } else {
            error(argPos(1), "unknown parent " + quoteToken(parent) +
                                 " (expected 'root' or a part declared before this one" +
                                 (type.parts.empty() ? std::string(")") : ": " + partList(type) + ")"));
            // Still declared (on the root), so that its shapes add no errors.
        }
        if (type.parts.size() >= std::size_t(kMaxModelParts)) {
            error(commandPos(), "too many parts: at most " + std::to_string(kMaxModelParts) + " in a model");
            return;
        }
        part.name = std::string(name);
        type.parts.push_back(std::move(part));
        building_->indexed.parts.push_back(span(argPos(0), name));
    }

    /// "unknown part 'b' of 'm' (expected a)": a part the block being read has not declared.
    std::string unknownBlockPart(std::string_view part) const {
        const ModelType& type = *building_->type;
        return "unknown part " + quoteToken(part) + " of " + modelText(*building_) +
               (type.parts.empty() ? std::string(" (declare it with '/part' first)")
                                   : " (expected " + partList(type) + ")");
    }

    /// The `part.shape` in argument i names a shape of the model being read.
    std::optional<int> modelShapeArgument(int i) {
        if (failed(i)) return std::nullopt;
        const ModelType& type = *building_->type;
        const std::string_view text = arg(i);
        const std::size_t dot = text.find('.');
        if (dot == std::string_view::npos) {
            error(argPos(i), "inside '/model' " + quoteToken(commandText()) +
                                 " takes a shape of the model, '<part>.<shape>', got " + quoteToken(text));
            return std::nullopt;
        }
        const int part = type.partIndex(text.substr(0, dot));
        if (part < 0) {
            error(argPos(i), unknownBlockPart(text.substr(0, dot)));
            return std::nullopt;
        }
        const int shape = type.shapeIndex(part, text.substr(dot + 1));
        if (shape < 0) {
            Pos shapePos = argPos(i);
            shapePos.column += static_cast<int>(dot) + 1;
            shapePos.length = static_cast<int>(text.size() - dot - 1);
            error(shapePos, "unknown shape " + quoteToken(text.substr(dot + 1)) + " on the part " +
                                quoteToken(text.substr(0, dot)) + " of " + modelText(*building_));
        }
        return shape < 0 ? std::nullopt : std::optional<int>(shape);
    }

    /// `/sphere|/cylinder|/box <part>.<shape> <size…> <cx> <cy> <cz> [<rx> <ry> <rz>]` in a model.
    void parseModelShape(ShapeKind kind, ObjectKind sized) {
        ModelType& type = *building_->type;
        const int sizeArgs = sizeArgCount(sized), withoutRotation = 1 + sizeArgs + 3;
        if (!expectArgs({withoutRotation, withoutRotation + 3})) return;
        bool ok = true;
        ModelShape shape;
        shape.kind = kind;
        shape.size = primitiveSize(sized, 1, ok);
        shape.centre = vec3(1 + sizeArgs, ok);
        setShapeRotation(shape, argCount() == withoutRotation + 3 ? vec3(4 + sizeArgs, ok) : Vec3{});
        if (failed(0)) return;
        const std::string_view text = arg(0);
        const std::size_t dot = text.find('.');
        const std::string_view partName = text.substr(0, dot);
        if (dot == std::string_view::npos || !isValidName(partName) || !isValidName(text.substr(dot + 1))) {
            error(argPos(0),
                  noteCharacters("a shape of a model is named '<part>.<shape>', got " + quoteToken(text),
                                 text, argPos(0)));
            return;
        }
        const std::string_view shapeName = text.substr(dot + 1);
        shape.part = type.partIndex(partName);
        if (shape.part < 0) {
            error(argPos(0), unknownBlockPart(partName));
            return;
        }
        if (type.shapeIndex(shape.part, shapeName) >= 0) {
            error(argPos(0), "duplicate shape " + quoteToken(text) + " in " + modelText(*building_));
            return;
        }
        if (type.shapes.size() >= std::size_t(kMaxModelShapes)) {
            error(commandPos(),
                  "too many shapes: at most " + std::to_string(kMaxModelShapes) + " in a model");
            return;
        }
        if (!ok) return;
        shape.name = std::string(shapeName);
        type.shapes.push_back(std::move(shape));
        building_->indexed.shapes.push_back(span(argPos(0), text));
    }

    /// The `/end` of a `/model` block: the type can be instanced from here on.
    void closeModel() {
        ModelBuild build = std::move(*building_);
        building_.reset();
        if (argCount() > 0) error(argPos(0), "'/end' takes no arguments");
        if (build.readFor) {
            // (A line that failed already names fewer shapes: not said twice.)
            if (errors_ == build.errorsBefore && !sameNames(*build.type, *build.readFor)) {
                error(build.defined, "the parts and shapes of '" + build.type->name +
                                         "' must not depend on its parameters: with these values the "
                                         "block names other parts or shapes than with its defaults");
            }
            return;
        }
        if (build.type->shapes.empty() && errors_ == build.errorsBefore) {
            // "model 'm' has no shapes", or "the model has no shapes" when its name was refused.
            error(build.defined, (build.named ? "model " : "") + modelText(build) +
                                     " has no shapes (put a '/sphere', '/cylinder' or '/box' named "
                                     "'<part>.<shape>' on one of its parts)");
        }
        if (!build.named) return;
        // Registered even with an error inside, so its instances do not add
        // "unknown command" errors.
        const std::shared_ptr<const ModelType> type = build.type;
        types_.emplace(type->name, TypeBook{type, build.namePos, start_});
        scene_.models.push_back(type);
        if (index_) {
            build.indexed.type = type;
            index_->models.push_back(std::move(build.indexed));
        }
    }

    void parseAnim() {
        if (!expectArgs({1, 2}) || failed(0)) return;
        // Only validates: /key needs no /anim (SPEC 6).
        if (argCount() == 1) {
            target(0, CameraTarget::Accepted, LightTarget::Accepted);
            return;
        }
        if (arg(0) == kCameraName) {
            error(argPos(1), "the camera has no parts");
            return;
        }
        if (lightNamed(arg(0))) {
            error(argPos(1), "a light has no parts");
            return;
        }
        if (arg(0).find('.') != std::string_view::npos) {
            error(argPos(0), "'/anim' with two arguments takes a name and a part, got " + quoteToken(arg(0)));
            return;
        }
        if (const std::optional<std::size_t> object = existing(arg(0), arg(0), argPos(0))) {
            partOf(*object, arg(1), argPos(1));
        }
    }

    void parseInterp() {
        if (!expectArgs({2, 6})) return;
        const std::optional<Target> t = target(0, CameraTarget::Accepted, LightTarget::Accepted);
        const std::optional<Easing> mode = easing(1, argCount());
        if (!t || !mode) return;
        std::optional<Pos>& before = t->camera       ? cameraInterp_
                                     : t->light >= 0 ? lightBook(*t).interp
                                                     : interps_[slotOf(*t)];
        if (before) {
            warning(argPos(0), "interpolation of " + quoteToken(targetName(*t)) +
                                   " is given again; it replaces the one at " + posText(*before));
        }
        before = argPos(0);
        trackOf(*t).interpolation = *mode;  // the last /interp of a target wins
    }

    /// "linear, ease, … or bounce": the language table's modes, for messages.
    static const std::string& modeWordList() {
        static const std::string list = [] {
            const std::span<const Interpolation> modes = interpolationModes();
            std::string words;
            for (std::size_t k = 0; k < modes.size(); ++k) {
                if (k > 0) words += k + 1 == modes.size() ? " or " : ", ";
                words += interpolationName(modes[k]);
            }
            return words;
        }();
        return list;
    }

    /// The mode word in argument i (SPEC 9.3).
    std::optional<Interpolation> interpolationMode(int i) {
        const std::optional<Interpolation> mode = modeFromWord(arg(i));
        if (!mode) {
            error(argPos(i), noteCharacters("unknown interpolation " + quoteToken(arg(i)) + " (expected " +
                                                modeWordList() + ")",
                                            arg(i), argPos(i)));
        }
        return mode;
    }

    void parseKey() {
        // Counted before anything else so that the limit holds for broken lines too.
        if (++keyLines_ > limits_.maxKeyLines) {
            error(commandPos(),
                  "too many '/key' lines: at most " + std::to_string(limits_.maxKeyLines) + " allowed");
            return;
        }
        const int n = argCount();
        if (n < 2) {
            error(commandPos(),
                  noteCharacters("'/key' takes 2 or 8 arguments (a time, a target and 0 or 6 numbers), got " +
                                     std::to_string(n),
                                 commandLine(), commandPos()));
            return;
        }
        // A word after the target that is not a mode names a property (SPEC 10.3),
        // unless it stands alone there: then it is read as a (mistyped) mode.
        const bool keysProperty = n > 2 && isWordArgument(2) && !modeFromWord(arg(2)) &&
                                  (n > 3 || findKeyProperty(arg(2)) != nullptr);
        const int firstNumber = keysProperty ? 3 : 2;
        // The key's mode (SPEC 9.3) is a last argument that is a word, or a
        // mode with numbers after it (`bezier x1 y1 x2 y2`, SPEC 10.4). Only a
        // line short enough to be a key has its tokens stored.
        constexpr int kMostKeyArgs = 13;  // time, target, six numbers, bezier and its four
        int modeAt = n;
        if (n <= kMostKeyArgs) {
            for (int i = firstNumber; i < n && modeAt == n; ++i) {
                if (!isWordArgument(i)) continue;
                const std::optional<Interpolation> mode = modeFromWord(arg(i));
                if (mode && modeNumberCount(*mode) > 0) modeAt = i;
            }
            if (modeAt == n && n > firstNumber && isWordArgument(n - 1)) modeAt = n - 1;
        }
        const int numbers = modeAt - firstNumber;
        if (keysProperty) return parsePropertyKey(numbers, modeAt);
        if (numbers != 0 && numbers != 6) {
            error(commandPos(), noteCharacters("'/key' takes 0 or 6 numbers after the target, got " +
                                                   std::to_string(numbers),
                                               commandLine(), commandPos()));
            return;
        }
        bool ok = true;
        const KeyTime time = keyTime(0, ok);
        const std::optional<Target> t = target(1, CameraTarget::Accepted, LightTarget::Accepted);
        Pose p;
        if (numbers == 6) p = pose(2, true, ok);
        std::optional<Easing> mode;
        if (modeAt < n) {
            mode = easing(modeAt, n);
            ok = ok && mode.has_value();
        }
        if (!t || !ok) return;
        if (t->light >= 0 && lightMotion(*t).ambient) {
            error(argPos(1), quoteToken(arg(1)) +
                                 " is an ambient light: it has no pose (key its intensity: "
                                 "'/key <t> " +
                                 std::string(arg(1)) + " intensity <i>')");
            return;
        }
        if (t->camera) {
            // `/camera` may come later: its pose is filled in at the end.
            cameraKeys_.push_back(
                {time, numbers == 6 ? std::optional<Pose>(p) : std::nullopt, mode, argPos(0)});
            return;
        }
        // Without numbers: an object's pose as created, a part's zero offset
        // and rotation, a light's identity.
        if (numbers == 0 && t->part < 0 && t->light < 0) p = scene_.objects[t->object].rest;
        addKey(*t, std::nullopt, time, {time.value, p, mode}, argPos(0));
    }

    /// `/key <t> <target> <property> <values…> [<mode>]` (SPEC 10.3), the
    /// property's word in argument 2, `numbers` values after it, then the mode at `modeAt`.
    void parsePropertyKey(int numbers, int modeAt) {
        const KeyPropertySpec* spec = findKeyProperty(arg(2));
        if (!spec) {
            std::string expected = "expected six numbers, a mode, or a property:";
            for (const KeyPropertySpec& p : keyProperties()) expected += " " + std::string(p.word);
            ClosestWord closest(arg(2));
            for (const KeyPropertySpec& p : keyProperties()) closest.consider(p.word);
            const std::string_view guess = closest.best();
            error(argPos(2),
                  noteCharacters("unknown key property " + quoteToken(arg(2)) +
                                     (guess.empty() ? "" : " (did you mean '" + std::string(guess) + "'?)") +
                                     "; " + expected,
                                 arg(2), argPos(2)));
            return;
        }
        if (numbers != spec->numbers) {
            error(argPos(2), quoteToken(spec->word) + " takes " + std::to_string(spec->numbers) +
                                 (spec->numbers == 1 ? " number (" : " numbers (") +
                                 std::string(spec->values) + "), got " + std::to_string(numbers));
            return;
        }
        bool ok = true;
        const KeyTime time = keyTime(0, ok);
        const std::optional<Target> t =
            target(1, CameraTarget::Accepted, LightTarget::Accepted, ShapeTarget::Accepted);
        Vec3 values;
        switch (spec->property) {
            case KeyProperty::Colour: {
                static constexpr std::array<std::string_view, 3> kWhat = {"red", "green", "blue"};
                for (int k = 0; k < 3; ++k) {
                    bool good = true;
                    values[k] = real(3 + k, good);
                    if (good && !(values[k] >= 0 && values[k] <= 255)) {
                        error(argPos(3 + k), std::string(kWhat[static_cast<std::size_t>(k)]) +
                                                 " must be from 0 to 255, got " + printable(arg(3 + k)));
                        good = false;
                    }
                    ok = ok && good;
                }
                break;
            }
            case KeyProperty::Intensity:
                values.x = nonNegative(3, "light intensity", ok);
                break;
            case KeyProperty::Zoom:
                values.x = positive(3, "screen distance", ok);
                break;
            case KeyProperty::Visible: {
                bool good = true;
                values.x = float(real(3, good));
                if (good && values.x != 0 && values.x != 1) {
                    error(argPos(3), "visible must be 0 or 1, got " + printable(arg(3)));
                    good = false;
                }
                ok = ok && good;
                break;
            }
        }
        std::optional<Easing> mode;
        if (modeAt < argCount() && spec->property == KeyProperty::Visible) {
            // SPEC 10.7: a target shows or hides at its keys, never in between.
            error(argPos(modeAt), "'visible' keys are always a step: a mode word is not allowed here");
            ok = false;
        } else if (modeAt < argCount()) {
            mode = easing(modeAt, argCount());
            ok = ok && mode.has_value();
        }
        if (!t || !ok) return;
        if (!hasProperty(*t, spec->property)) {
            error(argPos(2), quoteToken(spec->word) + " is not a property of " + targetText(*t) + " (" +
                                 quoteToken(spec->word) + " keys " + std::string(spec->targets) + ")");
            return;
        }
        addKey(*t, spec->property, time, {time.value, Pose{values, {}}, mode}, argPos(0));
    }

    /// `/drive <target> <channel> (<expression>)` (SPEC 10.7): the expression
    /// arrives compiled (SourceExpander); the drive goes into the track of the
    /// channel's property, beside its keys.
    void parseDrive() {
        if (!expectArgs({3})) return;
        const std::optional<Target> t =
            target(0, CameraTarget::Accepted, LightTarget::Accepted, ShapeTarget::Accepted);
        const std::optional<DriveChannel> channel = driveChannelFromWord(arg(1));
        if (!channel && !failed(1)) {
            std::string list;
            ClosestWord closest(arg(1));
            for (std::string_view c : driveChannelNames()) {
                list += " " + std::string(c);
                closest.consider(c);
            }
            const std::string_view guess = closest.best();
            error(argPos(1),
                  noteCharacters("unknown channel " + quoteToken(arg(1)) +
                                     (guess.empty() ? "" : " (did you mean '" + std::string(guess) + "'?)") +
                                     "; the channels are" + list,
                                 arg(1), argPos(1)));
        }
        const LogicalToken& expression = argToken(2);
        if (expression.form != TokenForm::Compiled && expression.form != TokenForm::Failed) {
            error(argPos(2), "a drive's expression stands in parentheses: write '(" +
                                 std::string(expression.written) + ")'");
            return;
        }
        if (!t || !channel || expression.form != TokenForm::Compiled) return;
        const std::string_view word = driveChannelName(*channel);
        if (!hasChannel(*t, *channel)) {
            error(argPos(1), quoteToken(word) + " is not a channel of " + targetText(*t) + " (" +
                                 quoteToken(word) + " drives " + channelTargets(*channel) + ")");
            return;
        }
        const TrackProperty property = *channel == DriveChannel::Intensity
                                           ? TrackProperty(KeyProperty::Intensity)
                                       : *channel == DriveChannel::D ? TrackProperty(KeyProperty::Zoom)
                                       : *channel >= DriveChannel::R ? TrackProperty(KeyProperty::Colour)
                                                                     : std::nullopt;
        Track& track = trackOf(*t, property);
        const auto slot = static_cast<std::size_t>(driveSlot(*channel));
        if (track.drives && track.drives->bySlot[slot]) {
            const f2::Drive& first = *track.drives->bySlot[slot];
            const std::string where = first.file == expander_.fileName(tokens_.pos.file)
                                          ? std::to_string(first.line) + ":" + std::to_string(first.column)
                                          : first.place();
            error(commandPos(), "second '/drive' of " + quoteToken(word) + " of " + targetText(*t) +
                                    " (the first is at " + where + ")");
            return;
        }
        auto drive = std::make_shared<f2::Drive>();
        drive->target = targetName(*t);
        drive->channel = *channel;
        drive->expression = std::string(expression.written);
        drive->file = expander_.fileName(tokens_.pos.file);
        drive->line = commandPos().line;
        drive->column = commandPos().column;
        drive->code = tokens_.compiled;
        auto drives = std::make_shared<TrackDrives>(track.drives ? *track.drives : TrackDrives{});
        drives->bySlot[slot] = drive;
        track.drives = std::move(drives);
        drives_.push_back(std::move(drive));
    }

    /// Whether `t` has channel `c` (SPEC 10.7): the pose's numbers where a
    /// pose is keyed, the others where keys of their property are allowed.
    bool hasChannel(Target t, DriveChannel c) const {
        switch (c) {
            case DriveChannel::Intensity:
                return hasProperty(t, KeyProperty::Intensity);
            case DriveChannel::D:
                return hasProperty(t, KeyProperty::Zoom);
            case DriveChannel::R:
            case DriveChannel::G:
            case DriveChannel::B:
                return hasProperty(t, KeyProperty::Colour);
            default:  // a shape has no pose of its own (SPEC 10.1)
                return t.shape < 0 &&
                       (t.light < 0 || !scene_.lightMotions[static_cast<std::size_t>(t.light)].ambient);
        }
    }

    /// What has channel `c`, for messages.
    static std::string channelTargets(DriveChannel c) {
        switch (c) {
            case DriveChannel::Intensity:
                return std::string(findKeyProperty("intensity")->targets);
            case DriveChannel::D:
                return std::string(findKeyProperty("d")->targets);
            case DriveChannel::R:
            case DriveChannel::G:
            case DriveChannel::B:
                return "the colour of " + std::string(findKeyProperty("colour")->targets);
            default:
                return "the pose of an object, a part, the camera or a light that is not ambient (not a "
                       "shape)";
        }
    }

    /// The scene's `/fps` is known at the end of the file: every drive's `time` is read at it.
    void finishDrives() {
        for (const std::shared_ptr<f2::Drive>& drive : drives_) {
            drive->fps = scene_.fps;
            scene_.drives.push_back(drive);
        }
        drives_ = {};
    }

    /// SPEC 10.3's table (and 10.7's `visible`): colour and visible on objects,
    /// parts and shapes, intensity on named lights, d on the camera.
    static bool hasProperty(Target t, KeyProperty property) {
        switch (property) {
            case KeyProperty::Colour:
            case KeyProperty::Visible:
                return !t.camera && t.light < 0;
            case KeyProperty::Intensity:
                return t.light >= 0;
            case KeyProperty::Zoom:
                return t.camera;
        }
        return false;
    }

    /// "the camera", "the light 'lamp'", "the robot 'f2'", "the part 'f2.head'", for messages.
    std::string targetText(Target t) const {
        if (t.camera) return "the camera";
        if (t.light >= 0) return lightText(t.light);
        if (t.shape >= 0) return "the shape " + quoteToken(targetName(t));
        if (t.part >= 0) return "the part " + quoteToken(targetName(t));
        const SceneObject& o = scene_.objects[t.object];
        return "the " + std::string(typeNameOf(o)) + " " + quoteToken(o.name);
    }

    /// Whether argument i is a word that may be a mode (not a number, not an expression).
    bool isWordArgument(int i) const {
        return argToken(i).form == TokenForm::Word && !arg(i).empty() && isNameStart(arg(i).front());
    }

    /// The mode word in argument i with the numbers after it up to argument
    /// `end` (SPEC 9.3; `bezier x1 y1 x2 y2`, SPEC 10.4).
    std::optional<Easing> easing(int i, int end) {
        const std::optional<Interpolation> mode = interpolationMode(i);
        if (!mode) return std::nullopt;
        const int given = end - i - 1, wanted = modeNumberCount(*mode);
        if (given != wanted) {
            const std::string word = quoteToken(arg(i));
            error(argPos(i), wanted == 0 ? word + " takes no numbers after it, got " + std::to_string(given)
                                         : word + " takes 4 numbers after it (x1 y1 x2 y2), got " +
                                               std::to_string(given));
            return std::nullopt;
        }
        Easing out{*mode};
        if (*mode == Interpolation::Bezier) {
            bool ok = true;
            auto unitX = [&](int k, std::string_view what) {
                bool good = true;
                const float v = real(k, good);
                if (good && !(v >= 0 && v <= 1)) {
                    error(argPos(k),
                          "bezier's " + std::string(what) + " must be from 0 to 1, got " + printable(arg(k)));
                    good = false;
                }
                ok = ok && good;
                return v;
            };
            out.curve.x1 = unitX(i + 1, "x1");
            out.curve.y1 = real(i + 2, ok);
            out.curve.x2 = unitX(i + 3, "x2");
            out.curve.y2 = real(i + 4, ok);
            if (!ok) return std::nullopt;
        }
        return out;
    }

    /// `/caption <from> <to> <x> <y> <size> "<text>" [colour <r> <g> <b>]` (SPEC 10.5).
    void parseCaption() {
        const int n = argCount();
        if (n != 6 && n != 10) {
            error(commandPos(), noteCharacters("'/caption' takes 6 or 10 arguments (from, to, x, y, size, "
                                               "\"text\", then optionally colour r g b), got " +
                                                   std::to_string(n),
                                               commandLine(), commandPos()));
            return;
        }
        bool ok = true;
        const KeyTime from = keyTime(0, ok), to = keyTime(1, ok);
        Caption caption;
        caption.x = real(2, ok);
        caption.y = real(3, ok);
        caption.size = positive(4, "caption size", ok);
        if (ok && caption.size > 1) {
            error(argPos(4),
                  "caption size is a fraction of the image height, at most 1, got " + printable(arg(4)));
            ok = false;
        }
        if (!failed(5)) {
            QuotedText text = readQuotedText(arg(5));
            if (text.ok) {
                caption.text = std::move(text.text);
            } else {
                // Columns inside the token hold as written unless `{ … }` changed it.
                const bool asWritten = argToken(5).written == argToken(5).text;
                Pos at = argPos(5);
                if (asWritten) at.column += static_cast<int>(text.offset);
                error(at, text.message);
                ok = false;
            }
        } else {
            ok = false;
        }
        if (n == 10) {
            if (arg(6) != "colour") {
                error(argPos(6), "expected 'colour' after the caption's text, got " + quoteToken(arg(6)));
                ok = false;
            } else {
                caption.colour = color(7, ok);
            }
        }
        if (!ok) return;
        caption.from = from.value;
        caption.to = to.value;
        scene_.captions.push_back(std::move(caption));
        captionBooks_.push_back({argPos(0), argPos(1), from.seconds, to.seconds});
    }

    /// The camera's keys, in file order, now that `/camera`'s pose is known.
    void addCameraKeys() {
        for (const CameraKey& k : cameraKeys_) {
            addKey(Target{0, -1, true}, std::nullopt, k.time,
                   {k.time.value, k.pose.value_or(scene_.camera.pose), k.mode}, k.origin);
        }
        cameraKeys_ = {};
    }

    int& trackBookIndex(Target t, TrackProperty property) {
        if (property == KeyProperty::Zoom) return cameraZoomBook_;
        if (property == KeyProperty::Intensity) return lightBook(t).intensityBook;
        if (property == KeyProperty::Colour) return colourTrackBooks_[targetTrackIndex(t, *property)];
        if (property == KeyProperty::Visible) return visibilityTrackBooks_[targetTrackIndex(t, *property)];
        if (t.camera) return cameraTrackBook_;
        if (t.light >= 0) return lightBook(t).poseBook;
        return poseTrackBooks_.try_emplace(slotOf(t), -1).first->second;
    }

    /// `key.time` is `time.value`: frames, or seconds until convertSecondsToFrames.
    void addKey(Target t, TrackProperty property, KeyTime time, const Key& key, Pos origin) {
        Track& track = trackOf(t, property);
        int& bookIndex = trackBookIndex(t, property);
        if (bookIndex < 0) {
            bookIndex = static_cast<int>(trackBooks_.size());
            trackBooks_.push_back({t, property, {}, true, {}});
        }
        TrackBook& book = trackBooks_[static_cast<std::size_t>(bookIndex)];
        if (time.seconds) {
            // Its place among the keys is known only with `/fps`: the track is
            // sorted at the end, and no key of it is replaced before that.
            book.sorted = false;
            book.inSeconds.push_back(static_cast<std::uint32_t>(track.keys.size()));
        }
        // Keys in increasing order (the usual case) stay sorted as they come; a
        // track that goes back is sorted once at the end, so a reversed file of
        // n keys costs O(n log n), not O(n²).
        if (book.sorted && !track.keys.empty()) {
            Key& last = track.keys.back();
            if (key.time == last.time) {
                warnReplaced(t, property, key.time, origin, book.origins.back());
                last = key;
                book.origins.back() = origin;
                return;
            }
            if (key.time < last.time) book.sorted = false;
        }
        track.keys.push_back(key);
        book.origins.push_back(origin);
    }

    /// A time in seconds (at `origin`) in frames at the scene's `/fps`; beyond
    /// the frame limit an error there.
    double framesOfSeconds(double seconds, Pos origin) {
        const double frames = seconds * scene_.fps;
        if (frames > limits_.maxKeyFrame) {
            error(origin, "a key time must be at most " + std::to_string(limits_.maxKeyFrame) +
                              " frames, got " + formatNumber(seconds) + " s = " + formatNumber(frames) +
                              " frames at " + std::to_string(scene_.fps) + " fps");
        }
        return frames;
    }

    /// Keys and captions written in seconds become frames at the scene's
    /// `/fps`, wherever it stands (SPEC 10.4); then a caption must end after it starts.
    void convertSecondsToFrames() {
        for (std::size_t k = 0; k < scene_.captions.size(); ++k) {
            Caption& c = scene_.captions[k];
            const CaptionBook& book = captionBooks_[k];
            if (book.fromInSeconds) c.from = framesOfSeconds(c.from, book.from);
            if (book.toInSeconds) c.to = framesOfSeconds(c.to, book.to);
            if (!(c.to > c.from)) {
                error(book.to, "a caption must end after it starts: it starts at frame " +
                                   formatNumber(c.from) + " and ends at frame " + formatNumber(c.to));
            }
        }
        captionBooks_ = {};
        for (TrackBook& book : trackBooks_) {
            std::vector<Key>& keys = trackOf(book.target, book.property).keys;
            for (std::uint32_t k : book.inSeconds)
                keys[k].time = framesOfSeconds(keys[k].time, book.origins[k]);
            book.inSeconds = {};
        }
    }

    void parseLookAt() {
        if (!firstOnly(lookAtSeen_) || !expectArgs({1, 3})) return;
        LookAt look;
        if (argCount() == 3) {
            bool ok = true;
            look.point = vec3(0, ok);
            if (!ok) return;
        } else {
            const std::optional<Target> t = target(0);
            if (!t) return;
            look.target = FrameRef{static_cast<std::uint32_t>(t->object), t->part};
        }
        scene_.camera.lookAt = look;
    }

    void parseAttach() {
        // `/attach <name> <target>`, or `/attach <name> <target> at <t>` (SPEC 10.7).
        if (argCount() == 3 && !failed(2) && arg(2) == kAtWord) {
            error(argPos(2), "'at' needs a time: '/attach <name> <target> at <t>'");
            return;
        }
        if (!expectArgs({2, 4})) return;
        const bool timed = argCount() == 4;
        if (timed && (failed(2) || arg(2) != kAtWord)) {
            if (!failed(2)) error(argPos(2), "expected 'at' before the time, got " + quoteToken(arg(2)));
            return;
        }
        const std::string_view name = arg(0);
        const bool camera = name == kCameraName;
        const std::optional<int> light = failed(0) ? std::nullopt : lightNamed(name);
        std::optional<std::size_t> child;
        // A `{ … }` that failed is reported already; the parent is still checked.
        if (light) {
            noteLightUse(*light, argPos(0), name);
            if (scene_.lightMotions[static_cast<std::size_t>(*light)].ambient) {
                error(argPos(0), quoteToken(name) +
                                     " is an ambient light: it has no position, so it cannot be attached");
                target(1);
                return;
            }
        } else if (!camera && !failed(0)) {
            if (name.find('.') != std::string_view::npos) {
                error(argPos(0),
                      "only a whole object or the camera can be attached, got " + quoteToken(name));
            } else {
                child = existing(name, name, argPos(0), true);
            }
        }
        if (timed && (camera || light)) {
            error(argPos(2), quoteToken(name) +
                                 " cannot change what it rides on: 'at' is for objects (one '/attach' of " +
                                 (camera ? "the camera" : "a light") + ", from the start)");
            return;
        }
        // `world` (unless an object takes the name) is no holder: it ends a ride (SPEC 10.7).
        const bool world = !failed(1) && arg(1) == kWorldName && !names_.contains(kWorldName);
        if (world && !timed) {
            error(argPos(1),
                  "'world' ends a ride, so it needs a time: '/attach <name> world at <t>' (without "
                  "'/attach' an object rides on nothing)");
            return;
        }
        const std::optional<Target> parent = world ? std::optional<Target>(Target{}) : target(1);
        bool ok = true;
        const KeyTime time = timed ? keyTime(3, ok) : KeyTime{};
        if ((!camera && !light && !child) || !parent || !ok) return;
        const std::optional<FrameRef> ref =
            world
                ? std::nullopt
                : std::optional<FrameRef>(FrameRef{static_cast<std::uint32_t>(parent->object), parent->part});
        if (timed) {
            const auto c = static_cast<std::uint32_t>(*child);
            if (ref && ref->object == c) {
                error(commandPos(), quoteToken(name) + " cannot be attached to " +
                                        (ref->part < 0 ? "itself" : "its own part"));
                return;
            }
            // Its time may be in seconds: checked at the end of the file (checkAttachChanges).
            attachChangeBooks_.push_back({c, time, ref, std::string(arg(1)), commandPos(), argPos(3)});
            return;
        }
        std::optional<Pos>& seen = camera  ? cameraAttached_
                                   : light ? lightBooks_[static_cast<std::size_t>(*light)].attached
                                           : books_[*child].attached;
        if (seen) {
            error(argPos(0), quoteToken(name) + " is already attached (at " + posText(*seen) +
                                 "); one '/attach' per name" +
                                 (child ? " without 'at' (a change of ride: '/attach " + std::string(name) +
                                              " <target> at <t>')"
                                        : std::string()));
            return;
        }
        if (camera || light) {  // nothing rides on the camera or a light, so they close no cycle
            (camera ? scene_.camera.attachedTo
                    : scene_.lightMotions[static_cast<std::size_t>(*light)].attachedTo) = ref;
            seen = commandPos();
            return;
        }
        const auto c = static_cast<std::uint32_t>(*child), p = ref->object;
        growSets();
        if (setTop_[findSet(p)] == c) {
            if (p == c) {
                error(commandPos(), quoteToken(name) + " cannot be attached to " +
                                        (ref->part < 0 ? "itself" : "its own part"));
            } else {
                error(commandPos(), "attaching " + quoteToken(name) + " to " + quoteToken(arg(1)) +
                                        " makes a cycle: " + quoteToken(scene_.objects[p].name) +
                                        " already rides on " + quoteToken(name));
            }
            return;
        }
        joinSets(c, p);
        scene_.objects[c].attachedTo = ref;
        seen = commandPos();
    }

    /// The `/attach … at` changes (SPEC 10.7), their times now in frames, go
    /// to their objects, sorted; then one time per name, and no cycle in any
    /// interval between two changes: a cycle can only be closed by a ride
    /// that starts at the interval's start, so each change climbs the rides
    /// that hold then, from its new holder, looking for its own object.
    void checkAttachChanges() {
        if (attachChangeBooks_.empty()) return;
        std::vector<AttachChangeBook>& books = attachChangeBooks_;
        for (AttachChangeBook& b : books) {
            if (b.time.seconds) b.time.value = framesOfSeconds(b.time.value, b.timePos);
        }
        // By time, file order among equal times.
        std::stable_sort(
            books.begin(), books.end(),
            [](const AttachChangeBook& a, const AttachChangeBook& b) { return a.time.value < b.time.value; });
        std::vector<bool> kept(books.size(), true);
        std::unordered_map<std::uint32_t, std::size_t> latest;  // object -> books index of its latest change
        for (std::size_t k = 0; k < books.size(); ++k) {
            const AttachChangeBook& b = books[k];
            SceneObject& object = scene_.objects[b.object];
            if (auto it = latest.find(b.object);
                it != latest.end() && books[it->second].time.value == b.time.value) {
                error(b.command, quoteToken(object.name) + " is already attached at frame " +
                                     formatNumber(b.time.value) + " (at " +
                                     posText(books[it->second].command) +
                                     "); one '/attach' per name and time");
                kept[k] = false;
                continue;
            }
            latest[b.object] = k;
            object.attachChanges.push_back({b.time.value, b.mount});
        }
        scene_.attachmentsChange = true;
        const std::size_t n = scene_.objects.size();
        // The rides as a forest that changes at each `at` time, in order: the
        // rides that change then are cut, then each new one is linked unless
        // the object is the top of its holder's tree (a cycle). O(log n) each.
        RideForest forest(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            if (const std::optional<FrameRef>& mount = scene_.objects[i].attachedTo)
                forest.link(i, mount->object);
        }
        for (std::size_t first = 0, end = 0; first < books.size() && !stopped_; first = end) {
            while (end < books.size() && books[end].time.value == books[first].time.value) ++end;
            for (std::size_t k = first; k < end; ++k) {
                if (kept[k]) forest.cut(books[k].object);
            }
            for (std::size_t k = first; k < end && !stopped_; ++k) {
                const AttachChangeBook& b = books[k];
                if (!kept[k] || !b.mount) continue;
                if (forest.top(b.mount->object) != b.object) {
                    forest.link(b.object, b.mount->object);
                } else {
                    reportRideCycle(b);
                }
            }
        }
        attachChangeBooks_ = {};
    }

    /// The change `b` closes a cycle at its time: told, and then taken as if
    /// the ride ended (one message per cycle).
    void reportRideCycle(const AttachChangeBook& b) {
        const double t = b.time.value;
        SceneObject& object = scene_.objects[b.object];
        // When the chain from the holder up to the object holds since: the
        // latest `at` on it (none: the start). The chain is at most every object long.
        std::optional<double> since;
        std::uint32_t x = b.mount->object;
        for (std::size_t steps = 0; x != b.object && steps < scene_.objects.size(); ++steps) {
            const SceneObject& holder = scene_.objects[x];
            const auto after =
                std::upper_bound(holder.attachChanges.begin(), holder.attachChanges.end(), t,
                                 [](double time, const AttachChange& c) { return time < c.time; });
            if (after != holder.attachChanges.begin())
                since = std::max(since.value_or(0.0), std::prev(after)->time);
            const std::optional<FrameRef> mount = mountAt(holder, t);
            if (!mount) break;
            x = mount->object;
        }
        error(b.command, "attaching " + quoteToken(object.name) + " to " + quoteToken(b.targetText) +
                             " at frame " + formatNumber(t) +
                             " makes a cycle: " + quoteToken(scene_.objects[b.mount->object].name) +
                             " rides on " + quoteToken(object.name) +
                             (since ? " from frame " + formatNumber(*since) : " from the start"));
        for (AttachChange& change : object.attachChanges) {
            if (change.time == t) change.mount.reset();
        }
    }

    // Attachment trees (see setParent_)
    void growSets() {
        while (setParent_.size() < scene_.objects.size()) {
            const auto i = static_cast<std::uint32_t>(setParent_.size());
            setParent_.push_back(i);
            setSize_.push_back(1);
            setTop_.push_back(i);
        }
    }

    std::uint32_t findSet(std::uint32_t x) {
        while (setParent_[x] != x) {
            setParent_[x] = setParent_[setParent_[x]];
            x = setParent_[x];
        }
        return x;
    }

    /// `child` (the top of its tree) now rides on `parent`.
    void joinSets(std::uint32_t child, std::uint32_t parent) {
        std::uint32_t a = findSet(child), b = findSet(parent);
        const std::uint32_t top = setTop_[b];
        if (setSize_[a] > setSize_[b]) std::swap(a, b);
        setParent_[a] = b;
        setSize_[b] += setSize_[a];
        setTop_[b] = top;
    }

    /// SceneDesc::attachOrder: each attached object after the attached object
    /// it rides on; every object that may ride when the rides change.
    void orderAttachments() {
        if (errors_ > 0) return;
        const std::vector<SceneObject>& objects = scene_.objects;
        if (scene_.attachmentsChange) {
            for (std::uint32_t i = 0; i < objects.size(); ++i) {
                if (objects[i].mayRide()) scene_.attachOrder.push_back(i);
            }
            return;
        }
        if (setParent_.empty()) return;
        std::vector<bool> placed(objects.size(), false);
        std::vector<std::uint32_t> chain;
        for (std::uint32_t i = 0; i < objects.size(); ++i) {
            // Climb while the objects are attached and not yet placed, then place them top first.
            for (std::uint32_t x = i; objects[x].attachedTo && !placed[x];
                 x = objects[x].attachedTo->object) {
                placed[x] = true;
                chain.push_back(x);
            }
            scene_.attachOrder.insert(scene_.attachOrder.end(), chain.rbegin(), chain.rend());
            chain.clear();
        }
    }

    void warnReplaced(Target t, TrackProperty property, double frame, Pos now, Pos before) {
        const std::string what =
            property ? "the " + std::string(keyProperties()[static_cast<std::size_t>(*property)].word) +
                           " of " + quoteToken(targetName(t))
                     : quoteToken(targetName(t));
        warning(now, "key frame " + formatNumber(frame) + " of " + what +
                         " is given again; it replaces the key at " + posText(before));
    }

    /// A target's `/interp` sets its property tracks' default mode too (SPEC 10.3).
    void applyInterpToPropertyTracks() {
        for (const TrackBook& book : trackBooks_) {
            // `visible` keys stay a step whatever the target's mode (SPEC 10.7).
            if (book.property && book.property != KeyProperty::Visible)
                trackOf(book.target, book.property).interpolation = trackOf(book.target).interpolation;
        }
    }

    /// Whole objects' colour tracks first, then parts', then shapes', so that
    /// the most specific track, applied last, wins.
    void orderColourTracks() {
        const auto rank = [](const TargetTrack& c) { return c.shape >= 0 ? 2 : c.target.part >= 0 ? 1 : 0; };
        std::stable_sort(scene_.colourTracks.begin(), scene_.colourTracks.end(),
                         [&](const TargetTrack& a, const TargetTrack& b) { return rank(a) < rank(b); });
        colourTrackBooks_ = {};  // its indices no longer match
        colourTrackIndex_ = {};
    }

    void sortUnsortedTracks() {
        for (TrackBook& book : trackBooks_) {
            if (book.sorted) continue;
            const Target t = book.target;
            std::vector<Key>& keys = trackOf(t, book.property).keys;
            std::vector<std::uint32_t> order(keys.size());
            std::iota(order.begin(), order.end(), 0u);
            // Stable: keys of one frame stay in file order, so the last one wins.
            std::stable_sort(order.begin(), order.end(),
                             [&](std::uint32_t a, std::uint32_t b) { return keys[a].time < keys[b].time; });
            std::vector<Key> sorted;
            sorted.reserve(keys.size());
            Pos lastOrigin;
            for (std::uint32_t k : order) {
                if (!sorted.empty() && sorted.back().time == keys[k].time) {
                    warnReplaced(t, book.property, keys[k].time, book.origins[k], lastOrigin);
                    sorted.back() = keys[k];
                } else {
                    sorted.push_back(keys[k]);
                }
                lastOrigin = book.origins[k];
            }
            keys = std::move(sorted);
            book.origins = {};
        }
    }

    // Symbol index (optional output)
    SourceLoc sourceLoc(Pos pos) const { return {expander_.fileName(pos.file), pos.line, pos.column}; }
    /// The name at `pos` as written: `r{i}` for the name r3 (up to a '.' outside braces).
    TokenSpan span(Pos pos, std::string_view name) const {
        int length = static_cast<int>(name.size());
        for (int k = 0; k < std::min(tokens_.count, kMaxStoredTokens); ++k) {
            const LogicalToken& t = tokens_.tokens[static_cast<std::size_t>(k)];
            if (t.column != pos.column || t.written == t.text) continue;
            int depth = 0;
            length = static_cast<int>(t.written.size());
            for (std::size_t i = 0; i < t.written.size(); ++i) {
                depth += t.written[i] == '{' ? 1 : t.written[i] == '}' ? -1 : 0;
                if (t.written[i] == '.' && depth == 0) {
                    length = static_cast<int>(i);
                    break;
                }
            }
        }
        return {sourceLoc(pos), length};
    }

    std::string_view fileName_;
    ParseLimits limits_;
    SymbolIndex* index_ = nullptr;
    SourceExpander expander_;
    SceneDesc scene_;
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
    /// Loop notes of objects defined in a loop ("in /repeat k = 0"); ObjectBook::loopNote - 1.
    std::vector<std::string> loopNotes_;
    std::size_t errors_ = 0, warnings_ = 0, droppedWarnings_ = 0;
    Pos firstDroppedWarning_;
    bool stopped_ = false;

    LogicalLine tokens_;
    std::size_t nameSuggestWork_ = 0;

    std::unordered_map<std::string, std::size_t, StringHash, std::equal_to<>> names_;
    std::vector<ObjectBook> books_;  ///< parallel to scene_.objects
    /// By target (slotOf): Parser::trackBooks_ index of its pose track, where
    /// its /interp was given, and its colour and visible tracks' indices in
    /// SceneDesc::colourTracks and visibilityTracks.
    std::unordered_map<std::uint64_t, int> poseTrackBooks_;
    std::unordered_map<std::uint64_t, std::optional<Pos>> interps_;
    std::unordered_map<std::uint64_t, std::size_t> colourTrackIndex_, visibilityTrackIndex_;
    /// Model types by name (SPEC 10.1): the robot, the human, then the file's.
    std::unordered_map<std::string, TypeBook, StringHash, std::equal_to<>> types_{
        {"robot", {robotModel(), std::nullopt, {}}}, {"human", {humanModel(), std::nullopt, {}}}};
    std::optional<ModelBuild> building_;
    SourceExpander::BlockStart start_;  ///< of the last `/model` block opened
    /// " (in /lamp L1)" while a block is read again for an instance (SPEC 10.6).
    std::string instanceNote_;
    std::vector<TrackBook> trackBooks_;
    std::optional<Pos> cameraSeen_, backgroundSeen_, fpsSeen_, lookAtSeen_, cameraAttached_, cameraInterp_;
    std::size_t keyLines_ = 0;
    std::size_t lightLines_ = 0;
    std::vector<CameraKey> cameraKeys_;
    std::vector<CaptionBook> captionBooks_;  ///< parallel to scene_.captions
    int cameraTrackBook_ = -1, cameraZoomBook_ = -1;
    float writtenAmbient_ = 0;  ///< every /amb_light's intensity as written, named or not
    /// Named lights (SPEC 10.2): name -> SceneDesc::lightMotions index, and their books.
    std::unordered_map<std::string, std::size_t, StringHash, std::equal_to<>> lightNames_;
    std::vector<LightBook> lightBooks_;
    std::vector<int> colourTrackBooks_;      ///< parallel to scene_.colourTracks: trackBooks_ indices
    std::vector<int> visibilityTrackBooks_;  ///< parallel to scene_.visibilityTracks: trackBooks_ indices
    /// Attachment trees as disjoint sets (union by size, path halving), each
    /// set knowing the object at its top: an `/attach` closes a cycle exactly
    /// when the new parent's top is the object being attached. Near O(1) per
    /// `/attach`, so a chain of a million attachments parses fast.
    std::vector<std::uint32_t> setParent_, setSize_, setTop_;
    /// `/attach … at` (SPEC 10.7) until the end of the file (checkAttachChanges).
    std::vector<AttachChangeBook> attachChangeBooks_;
    /// Every `/drive` (SPEC 10.7) until the end of the file, when `/fps` is known.
    std::vector<std::shared_ptr<f2::Drive>> drives_;
};

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
    return Parser(fileName, limits, nullptr).run(text);
}

ParseResult parseScene(std::string_view text, std::string_view fileName, const ParseLimits& limits,
                       SymbolIndex& index) {
    index.clear();
    return Parser(fileName, limits, &index).run(text);
}

ParseResult parseScene(std::string_view text, std::string_view fileName, const ParseLimits& limits,
                       SymbolIndex& index, const SourceOverlay& overlay) {
    index.clear();
    Parser parser(fileName, limits, &index);
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
    return Parser(path, limits, nullptr).run(file.text, std::pair{file.device, file.inode});
}

ParseResult parseSceneFile(const std::string& path) { return parseSceneFile(path, ParseLimits{}); }

}  // namespace f2
