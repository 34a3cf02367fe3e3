#include "core/parse/command_reader.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/parse/expression.h"
#include "core/parse/language.h"
#include "core/parse/lexer.h"
#include "core/parse/number.h"
#include "core/parse/quoted_text.h"
#include "core/parse/unusual_char.h"

namespace f2::parsing {

namespace {

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

}  // namespace

CommandReader::CommandReader(std::string_view fileName, const ParseLimits& limits)
    : fileName_(fileName), limits_(limits), expander_(expansionLimits(limits), *this) {}

ParseResult CommandReader::finishReading() {
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
        diagnostics_[i].message += r.inLoop
                                       ? " (and in " + n + (r.count == 1 ? " more pass)" : " more passes)")
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
    return result;
}

std::string CommandReader::posText(Pos p) const {
    std::string s = std::to_string(p.line) + ":" + std::to_string(p.column);
    return p.file == tokens_.pos.file ? s : expander_.fileName(p.file) + ":" + s;
}

void CommandReader::report(Severity severity, Pos pos, std::string message, LoopNote noted) {
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
        push({{expander_.fileName(pos.file), pos.line, pos.column}, severity, std::move(message), pos.length},
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

void CommandReader::push(Diagnostic diagnostic, Pos pos, bool inLoop) {
    diagnostics_.push_back(std::move(diagnostic));
    order_.push_back(pos);
    repeats_.push_back({0, inLoop});
}

Pos CommandReader::at(int column) const {
    Pos p = tokens_.pos;
    p.column = column;
    return p;
}

Pos CommandReader::tokenPos(int i) const {
    const LogicalToken& token = storedToken(i);
    Pos p = at(token.column);
    p.length = static_cast<int>(token.written.size());
    return p;
}

bool CommandReader::expectArgs(std::span<const int> allowed, int optionArgs) {
    const int n = argCount() - optionArgs;
    if (std::find(allowed.begin(), allowed.end(), n) != allowed.end()) return true;
    std::string list;
    std::size_t i = 0;
    for (int a : allowed) {
        if (i > 0) list += i + 1 == allowed.size() ? " or " : ", ";
        list += std::to_string(a);
        ++i;
    }
    const bool plural = allowed.size() > 1 || allowed.front() != 1;
    // A no-break space glues two arguments into one, so the count is the first thing wrong.
    error(commandPos(),
          noteCharacters(quoteToken(commandText()) + " takes " + list +
                             (plural ? " arguments" : " argument") + ", got " + std::to_string(n),
                         commandLine(), commandPos()));
    return false;
}

double CommandReader::number(int i, bool& ok) {
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

std::optional<double> CommandReader::secondsValue(std::string_view text) {
    if (text.size() < 2 || text.back() != 's') return std::nullopt;
    const ParsedNumber n = parseNumber(text.substr(0, text.size() - 1));
    if (n.status != NumberStatus::Ok) return std::nullopt;
    return n.value;
}

KeyTime CommandReader::keyTime(int i, bool& ok) {
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

float CommandReader::positive(int i, std::string_view what, bool& ok) {
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

float CommandReader::nonNegative(int i, std::string_view what, bool& ok) {
    bool good = true;
    const float v = real(i, good);
    if (good && v < 0) {
        error(argPos(i), std::string(what) + " must be >= 0, got " + printable(arg(i)));
        good = false;
    }
    ok = ok && good;
    return good ? v : 0.0f;
}

int CommandReader::whole(int i, std::string_view what, int lo, int hi, bool& ok) {
    bool good = true;
    double v = number(i, good);
    // SPEC 9.4: an expression within 1e-6 of a whole number gives that number.
    if (good && argToken(i).form == TokenForm::Expression) v = nearWhole(v).value_or(v);
    if (good && (v != std::floor(v) || v < lo || v > hi)) {
        error(argPos(i), std::string(what) + " must be a whole number from " + std::to_string(lo) + " to " +
                             std::to_string(hi) + ", got " + printable(arg(i)));
        good = false;
    }
    ok = ok && good;
    return good ? static_cast<int>(v) : lo;
}

Pose CommandReader::pose(int first, bool withRotation, bool& ok) {
    Pose p;
    p.position = vec3(first, ok);
    if (withRotation) p.rotation = vec3(first + 3, ok);
    return p;
}

Color8 CommandReader::color(int first, bool& ok) {
    static constexpr std::array<std::string_view, 3> kWhat = {"red", "green", "blue"};
    std::array<std::uint8_t, 3> c{};
    for (int k = 0; k < 3; ++k) {
        c[static_cast<std::size_t>(k)] =
            static_cast<std::uint8_t>(whole(first + k, kWhat[static_cast<std::size_t>(k)], 0, 255, ok));
    }
    return {c[0], c[1], c[2]};
}

bool CommandReader::firstOnly(std::optional<Pos>& seen) {
    if (seen) {
        error(commandPos(),
              "second " + quoteToken(commandText()) + " (the first is at " + posText(*seen) + ")");
        return false;
    }
    seen = commandPos();
    return true;
}

TokenSpan CommandReader::span(Pos pos, std::string_view name) const {
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

}  // namespace f2::parsing
