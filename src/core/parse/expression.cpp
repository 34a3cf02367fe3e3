#include "core/parse/expression.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

#include "core/parse/language.h"
#include "core/parse/lexer.h"
#include "core/parse/number.h"
#include "core/parse/unusual_char.h"

namespace f2 {

namespace {

/// SPEC 9.4: an integer field takes a value this close to a whole number.
constexpr double kWholeTolerance = 1e-6;

bool isDigit(char c) { return c >= '0' && c <= '9'; }

using Code = std::vector<ExprInstruction>;

/// A value while an expression is read: a number, or (compiling, SPEC
/// 10.7) the code that computes it from the inputs.
struct Value {
    double number = 0;
    Code code;  ///< not empty: computed per evaluation
    bool dynamic() const { return !code.empty(); }
};

/// Appends the code of `v` (a Push when it is a number).
void appendCode(Code& out, Value&& v) {
    if (!v.dynamic()) {
        out.push_back({ExprOp::Push, ExprFunction::Sin, 0, 0, v.number});
        return;
    }
    out.insert(out.end(), v.code.begin(), v.code.end());
}

ExprInstruction instruction(ExprOp op, std::size_t at, std::uint32_t index = 0) {
    return {op, ExprFunction::Sin, index, std::uint32_t(at), 0};
}

/// The code of `v` then `after`.
Value followedBy(Value v, ExprInstruction after) {
    Value out;
    appendCode(out.code, std::move(v));
    out.code.push_back(after);
    return out;
}

/// Recursive descent over
///   expression := and ('||' and)*
///   and        := equality ('&&' equality)*
///   equality   := relation (('==' | '!=') relation)?   (no chains: a == b == c is an error)
///   relation   := sum (('<' | '<=' | '>' | '>=') sum)?  (no chains: a < b < c is an error)
///   sum        := product (('+' | '-') product)*
///   product    := unary (('*' | '/' | '%') unary)*
///   unary      := ('-' | '+' | '!') unary | power
///   power      := primary ('^' unary)?          (right-associative, above unary minus)
///   primary    := number | variable | function '(' expression (',' expression)* ')'
///               | '(' expression ')'
/// The first error wins; after it every function returns 0 and unwinds.
///
/// What is not evaluated (the right side of `&&` and `||` once the left one
/// decides, the branch of `if` that is not returned) is still read: its
/// syntax, its names and its functions' argument counts are checked, but
/// nothing is computed, so a division by zero or a domain error there is no
/// error (SPEC 10.7).
class ExpressionParser {
   public:
    /// `inputs`: the names whose values are given at each evaluation of the
    /// compiled code (none: the text is evaluated now).
    ExpressionParser(std::string_view text, const Variables& variables,
                     std::span<const std::string_view> inputs = {})
        : text_(text), variables_(variables), inputs_(inputs) {}

    ExpressionResult whole() {
        Value v = expression();
        if (!failed_) {
            skipSpaces();
            if (pos_ < text_.size()) unexpected();
        }
        return result(v).first;
    }

    std::pair<ExpressionResult, ExpressionCode> parenthesized() {
        Value v = primary();
        if (!failed_) {
            skipSpaces();
            if (pos_ < text_.size()) {
                fail(pos_, "unexpected " + quoteToken(text_.substr(pos_, 1)) +
                               " after the ')' that closes the expression");
            }
        }
        return result(v);
    }

   private:
    std::pair<ExpressionResult, ExpressionCode> result(Value& v) const {
        ExpressionResult r;
        r.ok = !failed_;
        r.value =
            failed_ || v.dynamic() ? 0 : (v.number == 0 ? 0.0 : v.number);  // -0 becomes 0, as for numbers
        r.errorOffset = errorOffset_;
        r.errorLength = errorLength_;
        r.message = message_;
        r.followOn = followOn_;
        if (failed_ || !v.dynamic()) return {r, ExpressionCode::constant(r.value)};
        return {r, ExpressionCode(std::move(v.code))};
    }

    void fail(std::size_t offset, std::string message, std::size_t length = 0) {
        if (failed_) return;
        failed_ = true;
        errorOffset_ = offset;
        errorLength_ = length;
        message_ = std::move(message);
    }

    void skipSpaces() {
        while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
    }

    char peek() {
        skipSpaces();
        return pos_ < text_.size() ? text_[pos_] : '\0';
    }

    /// Whether `op` stands next (after spaces).
    bool peekIs(std::string_view op) {
        skipSpaces();
        return text_.substr(pos_).starts_with(op);
    }

    /// Reports what stands at pos_ where an operand or operator was expected.
    void unexpected() {
        if (pos_ >= text_.size()) {
            fail(pos_, "the expression ends too early");
            return;
        }
        const std::string_view rest = text_.substr(pos_);
        if (const auto c = unusualCharacterAt(rest)) {
            // Not '\xc2': a no-break space copied from a web page is named as such.
            fail(pos_, "unexpected " + c->name + " in the expression" +
                           (c->hint.empty() ? "" : " (" + c->hint + ")"));
            return;
        }
        // The operators of other languages, and these written by halves, teach the right one.
        if (rest.starts_with("=<") || rest.starts_with("=>")) {
            fail(pos_, quoteToken(rest.substr(0, 2)) + " is not an operator: write '" + rest[1] + "='");
            return;
        }
        if (rest.starts_with('=') && !rest.starts_with("==")) {
            fail(pos_, "'=' is not an operator: to compare, write '=='; to set a variable, use /let");
            return;
        }
        if (rest.starts_with('&') && !rest.starts_with("&&")) {
            fail(pos_, "'&' is not an operator: for 'and', write '&&'");
            return;
        }
        if (rest.starts_with('|') && !rest.starts_with("||")) {
            fail(pos_, "'|' is not an operator: for 'or', write '||'");
            return;
        }
        if (rest.starts_with('?')) {
            fail(pos_, "unexpected '?' in the expression: for a choice, write if(condition, a, b)");
            return;
        }
        if (isNameStart(rest[0])) {
            std::size_t end = 1;
            while (end < rest.size() && isNameChar(rest[end])) ++end;
            const std::string_view word = rest.substr(0, end);
            if (word == "and" || word == "or") {
                fail(pos_, "unexpected " + quoteToken(word) + " in the expression: for '" +
                               std::string(word) + "', write '" + (word == "and" ? "&&" : "||") + "'");
                return;
            }
        }
        // A two-character operator is quoted whole: "unexpected '=='".
        for (std::string_view op : {"==", "!=", "<=", ">=", "&&", "||"}) {
            if (rest.starts_with(op)) {
                fail(pos_, "unexpected " + quoteToken(op) + " in the expression");
                return;
            }
        }
        fail(pos_, "unexpected " + quoteToken(text_.substr(pos_, 1)) + " in the expression");
    }

    /// Guards every recursive step so that "((((…" cannot overflow the stack.
    bool enter(std::size_t at) {
        if (++depth_ > kMaxExpressionDepth) {
            fail(at, "the expression is nested more than " + std::to_string(kMaxExpressionDepth) +
                         " levels deep");
            return false;
        }
        return true;
    }

    /// `a op b` for the operator at `at`: folded now when both are numbers
    /// (an error at the operator if it fails), else code.
    Value binary(ExprOp op, Value a, Value b, std::size_t at) {
        if (failed_) return {};
        if (a.dynamic() || b.dynamic()) {
            Value out;
            appendCode(out.code, std::move(a));
            appendCode(out.code, std::move(b));
            out.code.push_back(instruction(op, at));
            return out;
        }
        if (skipping_ > 0) return {};  // not evaluated: its value is never used
        const ExprStep s = applyOperator(op, a.number, b.number);
        if (s.problem == ExprProblem::None) return {s.value, {}};
        // Where a condition known only per evaluation decides whether this
        // runs, its problem is one of the evaluations that run it.
        if (conditional_ > 0) {
            const ExprInstruction push{ExprOp::Push, ExprFunction::Sin, 0, std::uint32_t(at), a.number};
            return binary(op, Value{0, {push}}, std::move(b), at);
        }
        fail(at, operatorProblemText(op, s.problem));
        return {};
    }

    /// 1 if `v` is not 0, else 0.
    static Value toBool(Value v, std::size_t at) {
        if (!v.dynamic()) return {v.number != 0 ? 1.0 : 0.0, {}};
        return followedBy(std::move(v), instruction(ExprOp::ToBool, at));
    }

    /// `a && b` or `a || b` whose left side is code: `jump` skips b when a decides.
    Value shortCircuit(Value a, ExprOp jump, std::size_t at) {
        ++conditional_;
        Value b = jump == ExprOp::AndJump ? equality() : logicalAnd();
        --conditional_;
        if (failed_) return {};
        Code tail;
        appendCode(tail, std::move(b));
        tail.push_back(instruction(ExprOp::ToBool, at));
        Value out = followedBy(std::move(a), instruction(jump, at, std::uint32_t(tail.size())));
        out.code.insert(out.code.end(), tail.begin(), tail.end());
        return out;
    }

    /// Takes the ')' that closes the '(' at `open`, or reports what stands there.
    bool close(std::size_t open) {
        if (peek() == ')') {
            ++pos_;
            return true;
        }
        if (pos_ >= text_.size()) {
            fail(open, "this '(' has no matching ')'");
        } else {
            unexpected();
        }
        return false;
    }

    /// `a || b`: 1 if either is not 0, else 0; `b` is not evaluated when `a` is not 0.
    Value expression() {
        Value v = logicalAnd();
        while (!failed_ && peekIs("||")) {
            const std::size_t at = pos_;
            pos_ += 2;
            if (v.dynamic()) {
                v = shortCircuit(std::move(v), ExprOp::OrJump, at);
                continue;
            }
            const bool decided = v.number != 0;
            if (decided) ++skipping_;
            Value rhs = logicalAnd();
            if (decided) --skipping_;
            v = decided ? Value{1, {}} : toBool(std::move(rhs), at);
        }
        return v;
    }

    /// `a && b`: 1 if both are not 0, else 0; `b` is not evaluated when `a` is 0.
    Value logicalAnd() {
        Value v = equality();
        while (!failed_ && peekIs("&&")) {
            const std::size_t at = pos_;
            pos_ += 2;
            if (v.dynamic()) {
                v = shortCircuit(std::move(v), ExprOp::AndJump, at);
                continue;
            }
            const bool decided = v.number == 0;
            if (decided) ++skipping_;
            Value rhs = equality();
            if (decided) --skipping_;
            v = decided ? Value{} : toBool(std::move(rhs), at);
        }
        return v;
    }

    /// The comparison operator of `ops` that stands next, or an empty view.
    std::string_view comparison(std::initializer_list<std::string_view> ops) {
        for (std::string_view op : ops) {
            if (peekIs(op)) return op;
        }
        return {};
    }

    /// `a OP b` for `first` OP; a second comparison of the same level is an
    /// error that shows how to write both (`0 < x < 10` is no range test).
    void refuseChain(std::string_view first, std::initializer_list<std::string_view> ops) {
        if (failed_) return;
        const std::string_view second = comparison(ops);
        if (second.empty()) return;
        fail(pos_, "comparisons do not chain: to test both, write 'a " + std::string(first) + " b && b " +
                       std::string(second) + " c'; otherwise put the first in parentheses");
    }

    /// `a == b`, `a != b`: 1 or 0, exactly (every value is finite: no NaN).
    Value equality() {
        Value v = relation();
        if (failed_) return v;
        const std::string_view op = comparison({"==", "!="});
        if (op.empty()) return v;
        const std::size_t at = pos_;
        pos_ += 2;
        if (pos_ < text_.size() && text_[pos_] == '=') {  // JavaScript's '===' and '!=='
            fail(at, quoteToken(std::string(op) + "=") + " is not an operator: write " + quoteToken(op));
            return {};
        }
        Value rhs = relation();
        if (failed_) return {};
        refuseChain(op, {"==", "!="});
        return binary(op == "==" ? ExprOp::Eq : ExprOp::Ne, std::move(v), std::move(rhs), at);
    }

    /// `a < b`, `a <= b`, `a > b`, `a >= b`: 1 or 0.
    Value relation() {
        Value v = sum();
        if (failed_) return v;
        if (peekIs("<>")) {
            fail(pos_, "'<>' is not an operator: to test that two values differ, write '!='");
            return {};
        }
        const std::string_view op = comparison({"<=", ">=", "<", ">"});
        if (op.empty()) return v;
        const std::size_t at = pos_;
        pos_ += op.size();
        Value rhs = sum();
        if (failed_) return {};
        refuseChain(op, {"<=", ">=", "<", ">"});
        const ExprOp code = op == "<"    ? ExprOp::Lt
                            : op == "<=" ? ExprOp::Le
                            : op == ">"  ? ExprOp::Gt
                                         : ExprOp::Ge;
        return binary(code, std::move(v), std::move(rhs), at);
    }

    Value sum() {
        Value v = product();
        while (!failed_) {
            const char op = peek();
            if (op != '+' && op != '-') break;
            const std::size_t at = pos_++;
            Value rhs = product();
            v = binary(op == '+' ? ExprOp::Add : ExprOp::Sub, std::move(v), std::move(rhs), at);
        }
        return v;
    }

    Value product() {
        Value v = unary();
        while (!failed_) {
            const char op = peek();
            if (op != '*' && op != '/' && op != '%') break;
            const std::size_t at = pos_++;
            Value rhs = unary();
            if (failed_) break;
            const ExprOp code = op == '*' ? ExprOp::Mul : op == '/' ? ExprOp::Div : ExprOp::Mod;
            v = binary(code, std::move(v), std::move(rhs), at);
        }
        return v;
    }

    Value unary() {
        const char c = peek();
        // '!=' where an operand should be is not a '!': unexpected() names it.
        if (c != '-' && c != '+' && (c != '!' || peekIs("!="))) return power();
        const std::size_t at = pos_++;
        if (!enter(at)) return {};
        Value v = unary();
        --depth_;
        if (c == '+') return v;
        const ExprOp op = c == '!' ? ExprOp::Not : ExprOp::Neg;
        if (v.dynamic()) return followedBy(std::move(v), instruction(op, at));
        if (c == '!') return {v.number == 0 ? 1.0 : 0.0, {}};
        return {-v.number, {}};
    }

    Value power() {
        Value base = primary();
        if (failed_ || peek() != '^') return base;
        const std::size_t at = pos_++;
        if (!enter(at)) return {};
        Value exponent = unary();  // 2^-1 and 2^3^2 = 2^9
        --depth_;
        return binary(ExprOp::Pow, std::move(base), std::move(exponent), at);
    }

    Value primary() {
        const char c = peek();
        const std::size_t at = pos_;
        if (c == '(') {
            ++pos_;
            if (!enter(at)) return {};
            Value v = expression();
            --depth_;
            if (failed_ || !close(at)) return {};
            return v;
        }
        if (isDigit(c) || c == '.') return {number(), {}};
        if (isNameStart(c)) return name();
        unexpected();
        return {};
    }

    double number() {
        const std::size_t start = pos_;
        while (pos_ < text_.size() && (isDigit(text_[pos_]) || text_[pos_] == '.')) ++pos_;
        // An exponent only if digits follow: "2e" stays "2" then the name "e".
        if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
            std::size_t p = pos_ + 1;
            if (p < text_.size() && (text_[p] == '+' || text_[p] == '-')) ++p;
            if (p < text_.size() && isDigit(text_[p])) {
                pos_ = p;
                while (pos_ < text_.size() && isDigit(text_[pos_])) ++pos_;
            }
        }
        const std::string_view token = text_.substr(start, pos_ - start);
        const ParsedNumber n = parseNumber(token);
        if (n.status == NumberStatus::OutOfRange) {
            fail(start, "number " + quoteToken(token) + " is out of range");
        } else if (n.status != NumberStatus::Ok) {
            fail(start, "invalid number " + quoteToken(token));
        }
        return n.value;
    }

    Value name() {
        const std::size_t start = pos_;
        while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
        const std::string_view word = text_.substr(start, pos_ - start);
        const ExprFunctionInfo* function = findExpressionFunction(word);
        if (peek() == '(') {
            if (!function) {
                fail(start, "unknown function " + quoteToken(word) +
                                (word == "not" ? " (to negate, write '!')" : ""));
                return {};
            }
            return call(*function, start);
        }
        // An input (a drive's frame and time) is known only at each evaluation.
        for (std::size_t k = 0; k < inputs_.size(); ++k) {
            if (inputs_[k] != word) continue;
            if (skipping_ > 0) return {};  // not evaluated
            return {0, {instruction(ExprOp::Load, start, std::uint32_t(k))}};
        }
        if (const std::optional<double> v = variables_.find(word)) return {*v, {}};
        // A variable whose '/let' failed is known; where nothing is evaluated its value is not needed.
        if (variables_.isBroken(word) && skipping_ > 0) return {};
        if (variables_.isBroken(word)) {
            if (!failed_) followOn_ = true;
            fail(start, "variable " + quoteToken(word) + " has no value: its '/let' failed", word.size());
            return {};
        }
        if (function) {
            fail(start, quoteToken(word) + " is a function: write " + std::string(word) + "(...)",
                 word.size());
        } else {
            fail(start,
                 "unknown variable " + quoteToken(word) + (word == "not" ? " (to negate, write '!')" : ""),
                 word.size());
        }
        return {};
    }

    Value call(const ExprFunctionInfo& f, std::size_t at) {
        const std::size_t open = pos_++;  // the '('
        if (!enter(open)) return {};
        const bool isIf = f.function == ExprFunction::If;
        std::vector<Value> args;
        if (peek() != ')') {
            for (;;) {
                // if(c, a, b) evaluates c, then only the branch it returns; the
                // other, and any argument past the third, is read but not
                // evaluated. A c known only per evaluation decides nothing now.
                const bool skip =
                    isIf && !args.empty() &&
                    (args.size() > 2 || (!args[0].dynamic() && (args[0].number != 0) != (args.size() == 1)));
                // Its branches, when c is known only per evaluation, may not run.
                const bool conditional = isIf && !args.empty() && args[0].dynamic();
                if (skip) ++skipping_;
                if (conditional) ++conditional_;
                args.push_back(expression());
                if (conditional) --conditional_;
                if (skip) --skipping_;
                if (failed_) return {};
                if (peek() != ',') break;
                ++pos_;
            }
        }
        --depth_;
        if (!close(open)) return {};
        const int n = static_cast<int>(args.size());
        if (n < f.minArgs || (f.maxArgs >= 0 && n > f.maxArgs)) {
            std::string count =
                f.maxArgs < 0 ? "at least " + std::to_string(f.minArgs) : std::to_string(f.minArgs);
            const bool plural = f.minArgs != 1;
            fail(at, quoteToken(f.name) + " takes " + count + (plural ? " arguments" : " argument") +
                         ", got " + std::to_string(n) +
                         (isIf ? " (write if(condition, value if true, value if false))" : ""));
            return {};
        }
        if (skipping_ > 0) return {};  // not evaluated: no domain errors
        if (isIf) return choice(std::move(args), at);
        if (std::any_of(args.begin(), args.end(), [](const Value& a) { return a.dynamic(); }))
            return compiledCall(f, std::move(args), at);
        std::vector<double> numbers;
        for (const Value& a : args) numbers.push_back(a.number);
        const ExprStep s = applyFunction(f.function, numbers);
        if (s.problem == ExprProblem::None) return {s.value, {}};
        if (conditional_ > 0) return compiledCall(f, std::move(args), at);  // as in binary()
        fail(at, functionProblemText(f.function, numbers[0], s.problem));
        return {};
    }

    /// The code of a call of `f` on `args`.
    static Value compiledCall(const ExprFunctionInfo& f, std::vector<Value> args, std::size_t at) {
        Value out;
        for (Value& a : args) appendCode(out.code, std::move(a));
        ExprInstruction i = instruction(ExprOp::Call, at, std::uint32_t(args.size()));
        i.function = f.function;
        out.code.push_back(i);
        return out;
    }

    /// if(c, a, b): the branch c gives now, or code that takes it per evaluation.
    static Value choice(std::vector<Value> args, std::size_t at) {
        if (!args[0].dynamic()) return std::move(args[0].number != 0 ? args[1] : args[2]);
        Code otherwise;
        appendCode(otherwise, std::move(args[2]));
        Code then;
        appendCode(then, std::move(args[1]));
        then.push_back(instruction(ExprOp::Jump, at, std::uint32_t(otherwise.size())));
        Value out =
            followedBy(std::move(args[0]), instruction(ExprOp::IfJump, at, std::uint32_t(then.size())));
        out.code.insert(out.code.end(), then.begin(), then.end());
        out.code.insert(out.code.end(), otherwise.begin(), otherwise.end());
        return out;
    }

    std::string_view text_;
    const Variables& variables_;
    std::span<const std::string_view> inputs_;
    std::size_t pos_ = 0;
    int depth_ = 0;
    /// > 0 while reading what is not evaluated (SPEC 10.7).
    int skipping_ = 0;
    /// > 0 while compiling what a condition known only per evaluation may skip.
    int conditional_ = 0;
    bool failed_ = false;
    bool followOn_ = false;
    std::size_t errorOffset_ = 0;
    std::size_t errorLength_ = 0;
    std::string message_;
};

}  // namespace

Variables::Variables() { values_.emplace(kPredefinedVariables[0], std::numbers::pi); }

std::optional<double> Variables::find(std::string_view name) const {
    if (auto it = values_.find(name); it != values_.end()) return it->second;
    return std::nullopt;
}

void Variables::set(std::string_view name, double value) {
    if (auto it = broken_.find(name); it != broken_.end()) broken_.erase(it);
    if (auto it = values_.find(name); it != values_.end()) {
        it->second = value;
    } else {
        values_.emplace(std::string(name), value);
    }
}

void Variables::markBroken(std::string_view name) {
    erase(name);
    broken_.emplace(name);
}

bool Variables::isBroken(std::string_view name) const { return broken_.find(name) != broken_.end(); }

void Variables::erase(std::string_view name) {
    if (auto it = values_.find(name); it != values_.end()) values_.erase(it);
}

bool Variables::isPredefined(std::string_view name) {
    return std::find(kPredefinedVariables.begin(), kPredefinedVariables.end(), name) !=
           kPredefinedVariables.end();
}

std::vector<std::string_view> expressionFunctionNames() {
    std::vector<std::string_view> names;
    for (const ExprFunctionInfo& f : expressionFunctions()) names.push_back(f.name);
    return names;
}

ExpressionResult evaluateExpression(std::string_view text, const Variables& variables) {
    return ExpressionParser(text, variables).whole();
}

ExpressionResult evaluateParenthesized(std::string_view text, const Variables& variables) {
    return ExpressionParser(text, variables).parenthesized().first;
}

CompiledExpression compileParenthesized(std::string_view text, const Variables& variables,
                                        std::span<const std::string_view> inputs) {
    auto [result, code] = ExpressionParser(text, variables, inputs).parenthesized();
    return {std::move(result), std::move(code)};
}

std::optional<double> nearWhole(double value) {
    const double whole = std::round(value);
    if (std::fabs(value - whole) <= kWholeTolerance) return whole == 0 ? 0.0 : whole;
    return std::nullopt;
}

}  // namespace f2
