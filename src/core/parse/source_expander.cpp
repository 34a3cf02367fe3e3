#include "core/parse/source_expander.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <tuple>
#include <unordered_set>

#include "core/parse/language.h"
#include "core/parse/number.h"
#include "core/parse/unusual_char.h"
#include "core/scene/drive.h"

namespace f2 {

namespace {

/// Variables follow the name rule of objects (SPEC 9.4).
constexpr bool isVariableName(std::string_view s) { return isValidName(s); }

/// The words of the four commands the expander runs (core/parse/language.h).
const std::string_view kLet = command(CommandId::Let).name;
const std::string_view kRepeat = command(CommandId::Repeat).name;
const std::string_view kEnd = command(CommandId::End).name;
const std::string_view kInclude = command(CommandId::Include).name;
/// `/model … /end` (SPEC 10.1) shares `/end` with the loops: the expander pairs
/// them and hands the block's lines, its `/model` and `/end` included, to the parser.
const std::string_view kModel = command(CommandId::Model).name;

/// The first token of a line, cheaply (for the scan that pairs /repeat and /end).
std::string_view firstWord(std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '#') ++j;
    return line.substr(i, j - i);
}

/// Number of passes of `/repeat v from to step`: k = 0, 1, … while
/// from + k·step has not passed `to`. Exact for any count a scene can run;
/// beyond 2^53 only its size matters (it breaks the line limit).
double loopPasses(double from, double to, double step) {
    // from + k·step, rounded as the loop computes it, never moves back as k
    // grows, so "within" holds for k = 0 … n−1 and fails from n on, and n is
    // found by search in at most ~110 steps. (Walking k one by one near the
    // estimate hung on `/repeat i 1e16 1e16 1e-10`, where adding the step
    // changes nothing for 10^10 passes.)
    auto within = [&](double k) {
        const double v = from + k * step;
        return step > 0 ? v <= to : v >= to;
    };
    if (!within(0)) return 0;
    constexpr double kExactCounts = 9e15;  // below 2^53: every whole k is a double
    const double span = std::floor((to - from) / step);
    if (!(span < kExactCounts)) return span + 1;
    double inside = 0;                         // within(inside) holds
    double outside = std::max(span, 0.0) + 1;  // first guess of n
    for (double gap = 1; within(outside); gap *= 2) {
        inside = outside;
        outside += gap;
        if (outside >= kExactCounts) return outside;
    }
    while (outside - inside > 1) {
        const double middle = std::floor(inside + (outside - inside) / 2);
        (within(middle) ? inside : outside) = middle;
    }
    return outside;
}

/// A whole number in decimal digits, never in exponent form ("r{1e3}" is r1000).
std::string wholeText(double whole) {
    std::array<char, 400> buffer{};
    const int n = std::snprintf(buffer.data(), buffer.size(), "%.0f", whole);
    return std::string(buffer.data(), static_cast<std::size_t>(n > 0 ? n : 0));
}

/// Passes of a `/repeat` line whose bounds are numbers written out (no
/// expression, no variable) and that cannot fail, else nullopt: such an inner
/// loop runs the same passes on every pass of the loops around it.
std::optional<double> literalLoopPasses(std::string_view line) {
    LineTokens tokens;
    tokenizeLine(line, tokens);
    if (tokens.count != 4 && tokens.count != 5) return std::nullopt;
    const std::string_view variable = tokens.tokens[1].text;
    if (!isVariableName(variable) || Variables::isPredefined(variable)) return std::nullopt;
    double bounds[3] = {0, 0, 1};
    for (int i = 2; i < tokens.count; ++i) {
        const ParsedNumber n = parseNumber(tokens.tokens[static_cast<std::size_t>(i)].text);
        if (n.status != NumberStatus::Ok) return std::nullopt;
        bounds[i - 2] = n.value;
    }
    if (bounds[2] == 0) return std::nullopt;
    return loopPasses(bounds[0], bounds[1], bounds[2]);
}

}  // namespace

FileRead readSourceFile(const std::string& path, std::size_t maxBytes) {
    FileRead result;
    // O_NONBLOCK: opening a FIFO for reading must not wait for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        result.problem = std::strerror(errno);
        return result;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        result.problem = std::strerror(errno);
    } else if (S_ISDIR(st.st_mode)) {
        result.problem = "it is a directory";
    } else if (!S_ISREG(st.st_mode)) {
        result.problem = "it is not a regular file";
    } else if (static_cast<std::uint64_t>(st.st_size) > maxBytes) {
        result.problem = "the file is " + std::to_string(st.st_size) + " bytes, more than the limit of " +
                         std::to_string(maxBytes) + " bytes";
    }
    if (!result.problem.empty()) {
        ::close(fd);
        return result;
    }
    result.device = static_cast<std::uint64_t>(st.st_dev);
    result.inode = static_cast<std::uint64_t>(st.st_ino);
    result.text.reserve(static_cast<std::size_t>(st.st_size));
    std::array<char, 1 << 16> buffer;
    for (;;) {
        const ssize_t got = ::read(fd, buffer.data(), buffer.size());
        if (got < 0) {
            if (errno == EINTR) continue;
            result.problem = std::strerror(errno);
            break;
        }
        if (got == 0) break;
        if (result.text.size() + static_cast<std::size_t>(got) > maxBytes) {
            // The file grew while being read.
            result.problem = "the file is larger than the limit of " + std::to_string(maxBytes) + " bytes";
            break;
        }
        result.text.append(buffer.data(), static_cast<std::size_t>(got));
    }
    ::close(fd);
    result.ok = result.problem.empty();
    if (!result.ok) result.text.clear();
    return result;
}

std::optional<std::pair<std::uint64_t, std::uint64_t>> fileIdentity(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
    return std::pair{static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino)};
}

/// What one pass of a loop costs at least, and where its /end is: found once
/// per file, so that a loop that is skipped or run again costs nothing to find.
struct SourceExpander::LoopInfo {
    LineReader afterEnd{std::string_view()};  ///< reader state just after the /end line
    std::uint64_t passLines = 0;  ///< lines every pass reads: the body outside inner loops, and the /end
    std::uint64_t passBytes = 0;
    /// The same with every pass of the inner loops whose bounds are numbers
    /// (literalLoopPasses), valid when `innerDepth` more loops may still nest.
    double deepLines = 0, deepBytes = 0;
    int innerDepth = 0;
};

struct SourceExpander::SourceFile {
    std::string owned;
    std::string_view text;
    std::string directory;  ///< relative includes are read from here ("" = current directory)
    std::optional<std::pair<std::uint64_t, std::uint64_t>> identity;
    std::unordered_map<int, LoopInfo> loops;  ///< by the line number of the /repeat
    std::unordered_set<int> closedModels;     ///< line numbers of the /model blocks that have an /end

    /// Pairs each /repeat with its /end (a /repeat left open has no entry).
    /// A line longer than `maxLineBytes` is refused when read, so a loop on it never runs.
    void findLoops(std::uint64_t& lineCount, std::size_t maxLineBytes) {
        struct Open {
            int line;
            std::uint64_t lines = 0, bytes = 0;
            double deepLines = 0, deepBytes = 0;
            int innerDepth = 0;
            std::optional<double> passes;  ///< when its bounds are numbers
            bool model = false;            ///< a `/model` block, not a loop
        };
        std::vector<Open> open;
        LineReader reader(text);
        SourceLine line;
        while (reader.next(line)) {
            ++lineCount;
            const std::string_view word = firstWord(line.text);
            const std::uint64_t bytes = line.text.size() + 1;
            if (word == kEnd && !open.empty() && open.back().model) {
                // A model's block is read once: its lines count in the loop around it.
                const Open o = open.back();
                open.pop_back();
                closedModels.insert(o.line);
                if (!open.empty()) {
                    Open& outer = open.back();
                    outer.lines += o.lines + 1;
                    outer.bytes += o.bytes + bytes;
                    outer.deepLines += o.deepLines + 1;
                    outer.deepBytes += o.deepBytes + static_cast<double>(bytes);
                    outer.innerDepth = std::max(outer.innerDepth, o.innerDepth);
                }
                continue;
            }
            if (word == kEnd && !open.empty()) {
                const Open o = open.back();
                open.pop_back();
                const LoopInfo info{reader,
                                    o.lines + 1,
                                    o.bytes + bytes,
                                    o.deepLines + 1,
                                    o.deepBytes + static_cast<double>(bytes),
                                    o.innerDepth};
                loops[o.line] = info;
                if (!open.empty() && o.passes) {
                    Open& outer = open.back();
                    outer.deepLines += *o.passes * info.deepLines;
                    outer.deepBytes += *o.passes * info.deepBytes;
                    outer.innerDepth = std::max(outer.innerDepth, o.innerDepth + 1);
                }
                continue;
            }
            if (!open.empty()) {
                open.back().lines += 1;
                open.back().bytes += bytes;
                open.back().deepLines += 1;
                open.back().deepBytes += static_cast<double>(bytes);
            }
            if (word == kRepeat) {
                Open o;
                o.line = line.number;
                if (line.text.size() <= maxLineBytes) o.passes = literalLoopPasses(line.text);
                open.push_back(o);
            }
            if (word == kModel) {
                Open o;
                o.line = line.number;
                o.model = true;
                open.push_back(o);
            }
        }
    }
};

struct SourceExpander::OpenFile {
    const SourceFile* source;
    LineReader reader;
    int nameIndex;
    std::size_t loopBase;  ///< loops open when the file was entered
};

struct SourceExpander::OpenLoop {
    std::string variable;
    std::optional<double> saved;  ///< its value before the loop, restored after /end
    double from, step;
    std::uint64_t passes, pass;
    LineReader bodyStart;
};

SourceExpander::SourceExpander(const ExpansionLimits& limits, ExpansionSink& sink)
    : limits_(limits), sink_(sink) {}

SourceExpander::~SourceExpander() = default;

void SourceExpander::start(std::string_view text, std::string name,
                           std::optional<std::pair<std::uint64_t, std::uint64_t>> identity) {
    auto source = std::make_unique<SourceFile>();
    source->text = text;
    source->directory = std::filesystem::path(name).parent_path().string();
    source->identity = identity;
    source->findLoops(linesInFiles_, limits_.maxLineBytes);
    fileBytes_ += text.size();
    const int nameIndex = addFile(std::move(name));
    fileStack_.push_back({source.get(), LineReader(source->text), nameIndex, 0});
    sources_.push_back(std::move(source));
}

const std::string& SourceExpander::fileName(int index) const {
    return names_[static_cast<std::size_t>(index)];
}

int SourceExpander::addFile(std::string name) {
    for (std::size_t i = 0; i < names_.size(); ++i) {
        if (names_[i] == name) return static_cast<int>(i);
    }
    names_.push_back(std::move(name));
    return static_cast<int>(names_.size() - 1);
}

SourcePos SourceExpander::at(int column) const {
    return {lineNumber_, column, fileStack_.back().nameIndex, static_cast<std::uint32_t>(linesRead_)};
}

SourcePos SourceExpander::at(const LogicalToken& token) const {
    SourcePos pos = at(token.column);
    pos.length = static_cast<int>(token.written.size());
    return pos;
}

SourcePos SourceExpander::inExpression(int textColumn, const ExpressionResult& result) const {
    SourcePos pos = at(textColumn + static_cast<int>(result.errorOffset));
    pos.length = static_cast<int>(result.errorLength);
    return pos;
}

std::string SourceExpander::loopNote() const {
    if (loopStack_.empty()) return {};
    std::string note = " (in /repeat ";
    for (std::size_t i = 0; i < loopStack_.size(); ++i) {
        const OpenLoop& loop = loopStack_[i];
        if (i > 0) note += ", ";
        const double value = loop.from + static_cast<double>(loop.pass) * loop.step;
        note += loop.variable + " = " + formatNumber(value == 0 ? 0.0 : value);
    }
    note += ')';
    return note;
}

bool SourceExpander::next(LogicalLine& out) {
    while (!stopped_ && !fileStack_.empty()) {
        OpenFile& file = fileStack_.back();
        SourceLine line;
        if (!file.reader.next(line)) {
            fileStack_.pop_back();
            continue;
        }
        ++linesRead_;
        bytesRead_ += line.text.size() + 1;
        lineNumber_ = line.number;
        if (linesRead_ > limits_.maxLines) {
            error(at(1), "more than " + std::to_string(limits_.maxLines) +
                             " lines read in all (each pass of a loop and each include counts)");
            stopped_ = true;
            return false;
        }
        if (bytesRead_ > limits_.maxBytes) {
            error(at(1), "more than " + std::to_string(limits_.maxBytes) +
                             " bytes read in all (each pass of a loop and each include counts)");
            stopped_ = true;
            return false;
        }
        if (line.text.size() > limits_.maxLineBytes) {
            error(at(1), "line is " + std::to_string(line.text.size()) +
                             " bytes long, more than the limit of " + std::to_string(limits_.maxLineBytes) +
                             " bytes");
            continue;
        }
        tokenize(line.text, out);
        if (out.count == 0) continue;  // blank or comment
        const std::string_view command = out.tokens[0].text;
        if (command == kLet) {
            evaluateTokens(out, 2);
            runLet(out);
        } else if (command == kRepeat) {
            evaluateTokens(out, 2);
            runRepeat(out, line.number);
        } else if (command == kEnd && endsModel()) {
            ModelBlock& block = modelBlocks_.back();
            variables_ = std::move(block.outside);
            if (block.replay) fileStack_.pop_back();
            modelBlocks_.pop_back();
            return true;  // the parser closes the model
        } else if (command == kEnd) {
            runEnd(out);
        } else if (command == kModel) {
            if (!file.source->closedModels.contains(line.number)) {
                // Nothing after it in this file can be read as it was meant.
                error(at(out.tokens[0]), "'/model' without '/end' in the same file");
                file.reader = LineReader(std::string_view());
                continue;
            }
            evaluateTokens(out, 1);
            modelBlocks_.push_back({fileStack_.size(), loopStack_.size(), variables_, false});
            lastModelBlock_ = {file.source, file.reader, file.nameIndex};
            return true;
        } else if (command == kInclude) {
            runInclude(line.text, out);
        } else {
            // A `/drive`'s expression (its third argument) is computed every frame (SPEC 10.7).
            constexpr int kDriveExpression = 3;
            const CommandSpec* spec = findCommand(command);
            const bool drive = spec && spec->id == CommandId::Drive;
            if (sink_.knowsCommand(command)) evaluateTokens(out, 1, drive ? kDriveExpression : -1);
            return true;
        }
    }
    return false;
}

void SourceExpander::tokenize(std::string_view text, LogicalLine& out) {
    LineTokens tokens;
    tokenizeLine(text, tokens);
    out.count = tokens.count;
    const int stored = std::min(tokens.count, kMaxStoredTokens);
    for (int i = 0; i < stored; ++i) {
        const Token& t = tokens.tokens[static_cast<std::size_t>(i)];
        out.tokens[static_cast<std::size_t>(i)] = {t.text, t.text, t.column, TokenForm::Word, 0};
    }
    out.pos = at(1);
    out.raw = text;
}

bool SourceExpander::evaluateTokens(LogicalLine& line, int first, int compiledAt) {
    storage_.clear();
    struct Replaced {
        std::size_t token, offset, length;
    };
    std::array<Replaced, kMaxStoredTokens> replaced{};
    std::size_t replacedCount = 0;
    bool ok = true;
    const int stored = std::min(line.count, kMaxStoredTokens);
    for (int i = first; i < stored; ++i) {
        LogicalToken& token = line.tokens[static_cast<std::size_t>(i)];
        const std::size_t offset = storage_.size();
        if (i == compiledAt && token.text.starts_with('(')) {
            CompiledExpression c = compileParenthesized(token.text, variables_, kDriveInputs);
            if (!c.result.ok) {
                if (!c.result.followOn) error(inExpression(token.column, c.result), c.result.message);
                token.form = TokenForm::Failed;
                ok = false;
                continue;
            }
            token.form = TokenForm::Compiled;
            line.compiled = std::move(c.code);
            continue;
        }
        if (token.text.starts_with('(')) {
            // `(expr)s` is a time in seconds (SPEC 10.4): it becomes the word
            // `<value>s`, read as `2.5s` is.
            const bool seconds = token.text.size() > 2 && token.text.ends_with(")s");
            const std::string_view expression =
                seconds ? token.text.substr(0, token.text.size() - 1) : token.text;
            const ExpressionResult r = evaluateParenthesized(expression, variables_);
            if (!r.ok) {
                if (!r.followOn) error(inExpression(token.column, r), r.message);
                token.form = TokenForm::Failed;
                ok = false;
                continue;
            }
            token.form = seconds ? TokenForm::Word : TokenForm::Expression;
            token.value = r.value;
            storage_ += formatNumber(r.value);
            if (seconds) storage_ += 's';
        } else if (token.text.find('{') != std::string_view::npos) {
            // Each { … } becomes the whole number its expression gives: r{i+1} -> r3.
            const std::string_view text = token.text;
            std::size_t k = 0;
            while (k < text.size() && token.form != TokenForm::Failed) {
                if (text[k] != '{') {
                    storage_ += text[k++];
                    continue;
                }
                int depth = 0;
                std::size_t close = k;
                for (; close < text.size(); ++close) {
                    if (text[close] == '{') ++depth;
                    if (text[close] == '}' && --depth == 0) break;
                }
                const int braceColumn = token.column + static_cast<int>(k);
                if (close == text.size()) {
                    error(at(braceColumn), "this '{' has no matching '}'");
                    token.form = TokenForm::Failed;
                    break;
                }
                const ExpressionResult r = evaluateExpression(text.substr(k + 1, close - k - 1), variables_);
                if (!r.ok) {
                    if (!r.followOn) error(inExpression(braceColumn + 1, r), r.message);
                    token.form = TokenForm::Failed;
                    break;
                }
                const std::optional<double> whole = nearWhole(r.value);
                if (!whole) {
                    error(at(braceColumn),
                          "'{...}' in a name must give a whole number, got " + formatNumber(r.value));
                    token.form = TokenForm::Failed;
                    break;
                }
                storage_ += wholeText(*whole);
                k = close + 1;
            }
            if (token.form == TokenForm::Failed) {
                storage_.resize(offset);
                ok = false;
                continue;
            }
        } else {
            continue;
        }
        replaced[replacedCount++] = {static_cast<std::size_t>(i), offset, storage_.size() - offset};
    }
    // Views are taken only now: appending may have moved the storage.
    for (std::size_t r = 0; r < replacedCount; ++r) {
        line.tokens[replaced[r].token].text =
            std::string_view(storage_).substr(replaced[r].offset, replaced[r].length);
    }
    return ok;
}

std::optional<double> SourceExpander::numberArgument(const LogicalLine& line, int i, bool& ok) {
    const LogicalToken& token = line.tokens[static_cast<std::size_t>(i)];
    if (token.form == TokenForm::Failed) {
        ok = false;
        return std::nullopt;
    }
    if (token.form == TokenForm::Expression) return token.value;
    const ParsedNumber n = parseNumber(token.text);
    if (n.status != NumberStatus::Ok) {
        error(at(token), numberErrorMessage(token.text, n.status));
        ok = false;
        return std::nullopt;
    }
    return n.value;
}

bool SourceExpander::variableName(const LogicalToken& name, std::string_view cannotBe) {
    if (!isVariableName(name.text)) {
        error(at(name), "invalid variable name " + quoteToken(name.text) +
                            " (expected a letter or '_', then letters, digits or '_')");
        return false;
    }
    if (Variables::isPredefined(name.text)) {
        error(at(name), quoteToken(name.text) + " is predefined and cannot be " + std::string(cannotBe));
        return false;
    }
    return true;
}

std::string_view writtenCommand(const LogicalLine& line) {
    const LogicalToken& first = line.tokens[0];
    const LogicalToken& last =
        line.tokens[static_cast<std::size_t>(std::min(line.count, kMaxStoredTokens) - 1)];
    const auto begin = static_cast<std::size_t>(first.column - 1);
    return line.raw.substr(begin, static_cast<std::size_t>(last.column - 1) + last.written.size() - begin);
}

void SourceExpander::runLet(const LogicalLine& line) {
    if (line.count != 3) {
        // A no-break space glues the two arguments into one, so the count is the first thing wrong.
        error(at(line.tokens[0]),
              withUnusualCharacterNote(
                  "'/let' takes 2 arguments (a variable and a number), got " + std::to_string(line.count - 1),
                  writtenCommand(line), line.tokens[0].column));
        // Its uses would each add "unknown variable": one mistake, one error.
        const std::string_view variable = line.count > 1 ? line.tokens[1].text : std::string_view();
        if (isVariableName(variable) && !Variables::isPredefined(variable) && !variables_.find(variable))
            variables_.markBroken(variable);
        return;
    }
    const LogicalToken& name = line.tokens[1];
    const bool named = variableName(name, "redefined");
    bool ok = true;
    const std::optional<double> value = numberArgument(line, 2, ok);
    if (!named) return;
    if (ok && value) {
        variables_.set(name.text, *value);
    } else if (!variables_.find(name.text)) {
        variables_.markBroken(name.text);  // a defined variable keeps its value
    }
}

void SourceExpander::skipLoop(const LoopInfo& info) { fileStack_.back().reader = info.afterEnd; }

void SourceExpander::runRepeat(const LogicalLine& line, int lineNumber) {
    OpenFile& file = fileStack_.back();
    const SourcePos commandPos = at(line.tokens[0]);
    const auto found = file.source->loops.find(lineNumber);
    if (found == file.source->loops.end()) {
        // The rest of the file is not read: it would only add follow-on errors.
        error(commandPos, "'/repeat' without '/end' in the same file");
        file.reader = LineReader(std::string_view());
        return;
    }
    const LoopInfo& info = found->second;
    if (line.count != 4 && line.count != 5) {
        error(commandPos,
              withUnusualCharacterNote(
                  "'/repeat' takes 3 or 4 arguments (a variable, from, to and an optional step), got " +
                      std::to_string(line.count - 1),
                  writtenCommand(line), line.tokens[0].column));
        return skipLoop(info);
    }
    const LogicalToken& name = line.tokens[1];
    bool ok = variableName(name, "a loop variable");
    const std::optional<double> from = numberArgument(line, 2, ok);
    const std::optional<double> to = numberArgument(line, 3, ok);
    std::optional<double> step = 1.0;
    if (line.count == 5) {
        step = numberArgument(line, 4, ok);
        if (step && *step == 0) {
            error(at(line.tokens[4]), "the step of '/repeat' must not be 0");
            ok = false;
        }
    }
    if (!ok) return skipLoop(info);
    if (loopStack_.size() >= static_cast<std::size_t>(limits_.maxLoopDepth)) {
        error(commandPos, "loops are nested more than " + std::to_string(limits_.maxLoopDepth) + " deep");
        return skipLoop(info);
    }
    const double passes = loopPasses(*from, *to, *step);
    if (passes == 0) return skipLoop(info);
    // The limits are checked before the first pass: every pass reads at least
    // its own lines, so a loop that cannot fit fails now, not after an hour.
    // Inner loops with numbers for bounds count too, unless they would nest
    // too deep (then they are skipped with an error, and read nothing).
    const bool deep = loopStack_.size() + 1 + static_cast<std::size_t>(info.innerDepth) <=
                      static_cast<std::size_t>(limits_.maxLoopDepth);
    const double lines = passes * (deep ? info.deepLines : static_cast<double>(info.passLines));
    const double bytes = passes * (deep ? info.deepBytes : static_cast<double>(info.passBytes));
    // Reading stops there, as when the limit is reached line by line.
    if (static_cast<double>(linesRead_) + lines > static_cast<double>(limits_.maxLines)) {
        error(commandPos, "this loop would read at least " + wholeText(lines) + " lines (" +
                              wholeText(passes) + " passes) after " + std::to_string(linesRead_) +
                              ", more than the limit of " + std::to_string(limits_.maxLines) +
                              " lines read in all");
        stopped_ = true;
        return;
    }
    if (static_cast<double>(bytesRead_) + bytes > static_cast<double>(limits_.maxBytes)) {
        error(commandPos, "this loop would read at least " + wholeText(bytes) + " bytes (" +
                              wholeText(passes) + " passes) after " + std::to_string(bytesRead_) +
                              ", more than the limit of " + std::to_string(limits_.maxBytes) +
                              " bytes read in all");
        stopped_ = true;
        return;
    }
    loopStack_.push_back({std::string(name.text), variables_.find(name.text), *from, *step,
                          static_cast<std::uint64_t>(passes), 0, file.reader});
    variables_.set(name.text, *from);
}

void SourceExpander::replayModelBlock(const BlockStart& start) {
    fileStack_.push_back(
        {static_cast<const SourceFile*>(start.source), start.reader, start.nameIndex, loopStack_.size()});
    modelBlocks_.push_back({fileStack_.size(), loopStack_.size(), variables_, true});
}

bool SourceExpander::endsModel() const {
    return !modelBlocks_.empty() && modelBlocks_.back().fileDepth == fileStack_.size() &&
           modelBlocks_.back().loopDepth == loopStack_.size();
}

void SourceExpander::runEnd(const LogicalLine& line) {
    OpenFile& file = fileStack_.back();
    if (loopStack_.size() == file.loopBase) {
        error(at(line.tokens[0]), "'/end' without '/repeat'");
        return;
    }
    if (line.count > 1) error(at(line.tokens[1]), "'/end' takes no arguments");
    OpenLoop& loop = loopStack_.back();
    if (++loop.pass < loop.passes) {
        const double value = loop.from + static_cast<double>(loop.pass) * loop.step;
        variables_.set(loop.variable, value == 0 ? 0.0 : value);
        file.reader = loop.bodyStart;
        return;
    }
    if (loop.saved) {
        variables_.set(loop.variable, *loop.saved);
    } else {
        variables_.erase(loop.variable);
    }
    loopStack_.pop_back();
}

void SourceExpander::runInclude(std::string_view raw, const LogicalLine& line) {
    const SourcePos commandPos = at(line.tokens[0]);
    // The path: a text in double quotes (kept as written, spaces and '#'
    // included), or one argument.
    std::size_t i = static_cast<std::size_t>(line.tokens[0].column - 1) + line.tokens[0].text.size();
    while (i < raw.size() && (raw[i] == ' ' || raw[i] == '\t')) ++i;
    std::string path;
    int pathColumn = static_cast<int>(i) + 1;
    if (i < raw.size() && raw[i] == '"') {
        const std::size_t close = raw.find('"', i + 1);
        if (close == std::string_view::npos) {
            error(at(pathColumn), "this '\"' has no closing '\"'");
            return;
        }
        path = std::string(raw.substr(i + 1, close - i - 1));
        std::size_t j = close + 1;
        while (j < raw.size() && (raw[j] == ' ' || raw[j] == '\t')) ++j;
        if (j < raw.size() && raw[j] != '#') {
            error(at(static_cast<int>(j) + 1), "unexpected text after the quoted path of '/include'");
            return;
        }
        if (path.empty()) {
            error(at(pathColumn), "empty path in '/include'");
            return;
        }
    } else {
        if (line.count != 2) {
            error(commandPos,
                  "'/include' takes 1 argument (a path, in double quotes if it has spaces), got " +
                      std::to_string(line.count - 1));
            return;
        }
        LogicalLine substituted = line;
        if (!evaluateTokens(substituted, 1)) return;
        path = std::string(substituted.tokens[1].text);
        pathColumn = line.tokens[1].column;
    }
    const SourcePos pathPos = at(pathColumn);
    if (fileStack_.size() > static_cast<std::size_t>(limits_.maxIncludeDepth)) {
        error(pathPos, "includes are nested more than " + std::to_string(limits_.maxIncludeDepth) + " deep");
        return;
    }
    namespace fs = std::filesystem;
    const OpenFile& including = fileStack_.back();
    fs::path resolved(path);
    if (resolved.is_relative() && !including.source->directory.empty()) {
        resolved = fs::path(including.source->directory) / resolved;
    }
    const int nameIndex = addFile(resolved.lexically_normal().string());
    const SourceFile* source = loadFile(names_[static_cast<std::size_t>(nameIndex)], pathPos);
    if (!source) return;
    for (std::size_t k = 0; k < fileStack_.size(); ++k) {
        if (fileStack_[k].source->identity != source->identity) continue;
        std::string chain;
        for (std::size_t m = k; m < fileStack_.size(); ++m)
            chain += quotePath(fileName(fileStack_[m].nameIndex)) + " -> ";
        chain += quotePath(fileName(nameIndex));
        error(pathPos, "include cycle: " + chain);
        return;
    }
    fileStack_.push_back({source, LineReader(source->text), nameIndex, loopStack_.size()});
}

const SourceExpander::SourceFile* SourceExpander::loadFile(const std::string& path, SourcePos at) {
    const std::string prefix = "cannot include " + quotePath(path) + ": ";
    // An overlaid text that is not on disk gets an identity of its own, for cycles.
    const std::string* overlaid = nullptr;
    if (overlay_) {
        if (const auto it = overlay_->find(path); it != overlay_->end()) overlaid = &it->second;
    }
    auto identity = fileIdentity(path);
    if (!identity && overlaid) identity = std::pair{~std::uint64_t{0}, std::hash<std::string>{}(path)};
    // A file read before is not read again (a loop may include it a million times).
    if (identity) {
        for (const auto& s : sources_) {
            if (s->identity == identity) return s.get();
        }
    }
    const std::size_t budget = limits_.maxFileBytes - std::min(limits_.maxFileBytes, fileBytes_);
    FileRead read;
    if (!overlaid) {
        read = readSourceFile(path, budget);
    } else if (overlaid->size() > budget) {
        read.problem = "the file is " + std::to_string(overlaid->size()) + " bytes, more than the limit of " +
                       std::to_string(budget) + " bytes";
    } else {
        read.ok = true;
        read.text = *overlaid;
        std::tie(read.device, read.inode) = *identity;
    }
    if (!read.ok) {
        if (read.problem.starts_with("the file is")) {
            read.problem += " (for all the files of the scene together)";
        }
        error(at, prefix + read.problem);
        return nullptr;
    }
    auto source = std::make_unique<SourceFile>();
    source->owned = std::move(read.text);
    source->text = source->owned;
    source->directory = std::filesystem::path(path).parent_path().string();
    source->identity = std::pair{read.device, read.inode};
    source->findLoops(linesInFiles_, limits_.maxLineBytes);
    fileBytes_ += source->text.size();
    sources_.push_back(std::move(source));
    return sources_.back().get();
}

}  // namespace f2
