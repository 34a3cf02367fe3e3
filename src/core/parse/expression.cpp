#include "core/parse/expression.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <vector>

#include "core/parse/language.h"
#include "core/parse/lexer.h"
#include "core/parse/number.h"
#include "core/parse/unusual_char.h"

namespace f2 {

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
/// SPEC 9.4: an integer field takes a value this close to a whole number.
constexpr double kWholeTolerance = 1e-6;

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Trigonometry in degrees. The angle is first reduced exactly (fmod is exact),
// so that the multiples of 90 give exact 0 and ±1: cos(90) is 0, not 6e-17.
double sinDegrees(double degrees) {
    const double r = std::fmod(degrees, 360.0);
    if (r == 0 || r == 180 || r == -180) return 0;
    if (r == 90 || r == -270) return 1;
    if (r == 270 || r == -90) return -1;
    return std::sin(r * kRadiansPerDegree);
}

double cosDegrees(double degrees) {
    const double r = std::fmod(degrees, 360.0);
    if (r == 0) return 1;
    if (r == 180 || r == -180) return -1;
    if (r == 90 || r == -90 || r == 270 || r == -270) return 0;
    return std::cos(r * kRadiansPerDegree);
}

/// tan of an odd multiple of 90 has no value; the caller reports it.
std::optional<double> tanDegrees(double degrees) {
    const double r = std::fmod(degrees, 180.0);
    if (r == 90 || r == -90) return std::nullopt;
    if (r == 0) return 0.0;
    if (r == 45 || r == -135) return 1.0;
    if (r == -45 || r == 135) return -1.0;
    return std::tan(r * kRadiansPerDegree);
}

enum class Function {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,
    Sqrt,
    Abs,
    Floor,
    Ceil,
    Exp,
    Log,
    Round,
    Min,
    Max,
    If
};

struct FunctionInfo {
    std::string_view name;
    Function function;
    int minArgs;
    int maxArgs;  ///< -1: any number
};

constexpr std::array<FunctionInfo, 17> kFunctions = {{
    {"sin", Function::Sin, 1, 1},
    {"cos", Function::Cos, 1, 1},
    {"tan", Function::Tan, 1, 1},
    {"asin", Function::Asin, 1, 1},
    {"acos", Function::Acos, 1, 1},
    {"atan", Function::Atan, 1, 1},
    {"atan2", Function::Atan2, 2, 2},
    {"sqrt", Function::Sqrt, 1, 1},
    {"abs", Function::Abs, 1, 1},
    {"floor", Function::Floor, 1, 1},
    {"ceil", Function::Ceil, 1, 1},
    {"exp", Function::Exp, 1, 1},
    {"log", Function::Log, 1, 1},
    {"round", Function::Round, 1, 1},
    {"min", Function::Min, 1, -1},
    {"max", Function::Max, 1, -1},
    {"if", Function::If, 3, 3},  // SPEC 10.7: evaluates only the branch it returns
}};

const FunctionInfo* findFunction(std::string_view name) {
    for (const FunctionInfo& f : kFunctions) {
        if (f.name == name) return &f;
    }
    return nullptr;
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
    ExpressionParser(std::string_view text, const Variables& variables)
        : text_(text), variables_(variables) {}

    ExpressionResult whole() {
        const double v = expression();
        if (!failed_) {
            skipSpaces();
            if (pos_ < text_.size()) unexpected();
        }
        return result(v);
    }

    ExpressionResult parenthesized() {
        const double v = primary();
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
    ExpressionResult result(double v) const {
        ExpressionResult r;
        r.ok = !failed_;
        r.value = failed_ ? 0 : (v == 0 ? 0.0 : v);  // -0 becomes 0, as for numbers
        r.errorOffset = errorOffset_;
        r.errorLength = errorLength_;
        r.message = message_;
        r.followOn = followOn_;
        return r;
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

    /// A finite result, or an error at the operator or function at `at`.
    double checked(double v, std::size_t at, std::string_view what) {
        if (skipping_ > 0) return 0;  // not evaluated: its value is never used
        if (!failed_ && !std::isfinite(v)) {
            fail(at, "the result of " + std::string(what) + " is not finite");
            return 0;
        }
        return v;
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
    double expression() {
        double v = logicalAnd();
        while (!failed_ && peekIs("||")) {
            pos_ += 2;
            const bool decided = v != 0;
            if (decided) ++skipping_;
            const double rhs = logicalAnd();
            if (decided) --skipping_;
            v = decided || rhs != 0 ? 1 : 0;
        }
        return v;
    }

    /// `a && b`: 1 if both are not 0, else 0; `b` is not evaluated when `a` is 0.
    double logicalAnd() {
        double v = equality();
        while (!failed_ && peekIs("&&")) {
            pos_ += 2;
            const bool decided = v == 0;
            if (decided) ++skipping_;
            const double rhs = equality();
            if (decided) --skipping_;
            v = !decided && rhs != 0 ? 1 : 0;
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
    double equality() {
        const double v = relation();
        if (failed_) return v;
        const std::string_view op = comparison({"==", "!="});
        if (op.empty()) return v;
        const std::size_t at = pos_;
        pos_ += 2;
        if (pos_ < text_.size() && text_[pos_] == '=') {  // JavaScript's '===' and '!=='
            fail(at, quoteToken(std::string(op) + "=") + " is not an operator: write " + quoteToken(op));
            return 0;
        }
        const double rhs = relation();
        if (failed_) return 0;
        refuseChain(op, {"==", "!="});
        return (v == rhs) == (op == "==") ? 1 : 0;
    }

    /// `a < b`, `a <= b`, `a > b`, `a >= b`: 1 or 0.
    double relation() {
        const double v = sum();
        if (failed_) return v;
        if (peekIs("<>")) {
            fail(pos_, "'<>' is not an operator: to test that two values differ, write '!='");
            return 0;
        }
        const std::string_view op = comparison({"<=", ">=", "<", ">"});
        if (op.empty()) return v;
        pos_ += op.size();
        const double rhs = sum();
        if (failed_) return 0;
        refuseChain(op, {"<=", ">=", "<", ">"});
        if (op == "<") return v < rhs ? 1 : 0;
        if (op == "<=") return v <= rhs ? 1 : 0;
        if (op == ">") return v > rhs ? 1 : 0;
        return v >= rhs ? 1 : 0;
    }

    double sum() {
        double v = product();
        while (!failed_) {
            const char op = peek();
            if (op != '+' && op != '-') break;
            const std::size_t at = pos_++;
            const double rhs = product();
            v = checked(op == '+' ? v + rhs : v - rhs, at, op == '+' ? "'+'" : "'-'");
        }
        return v;
    }

    double product() {
        double v = unary();
        while (!failed_) {
            const char op = peek();
            if (op != '*' && op != '/' && op != '%') break;
            const std::size_t at = pos_++;
            const double rhs = unary();
            if (failed_) break;
            if (op == '*') {
                v = checked(v * rhs, at, "'*'");
            } else if (skipping_ > 0) {
                v = 0;  // not evaluated
            } else if (rhs == 0) {
                fail(at, op == '/' ? "division by zero" : "remainder of a division by zero");
            } else if (op == '/') {
                v = checked(v / rhs, at, "'/'");
            } else {
                // The remainder takes the sign of the divisor: 7 % -3 = -2, -7 % 3 = 2.
                double r = std::fmod(v, rhs);
                if (r != 0 && ((r < 0) != (rhs < 0))) r += rhs;
                v = r;
            }
        }
        return v;
    }

    double unary() {
        const char c = peek();
        // '!=' where an operand should be is not a '!': unexpected() names it.
        if (c != '-' && c != '+' && (c != '!' || peekIs("!="))) return power();
        const std::size_t at = pos_++;
        if (!enter(at)) return 0;
        const double v = unary();
        --depth_;
        if (c == '!') return v == 0 ? 1 : 0;
        return c == '-' ? -v : v;
    }

    double power() {
        const double base = primary();
        if (failed_ || peek() != '^') return base;
        const std::size_t at = pos_++;
        if (!enter(at)) return 0;
        const double exponent = unary();  // 2^-1 and 2^3^2 = 2^9
        --depth_;
        if (failed_ || skipping_ > 0) return 0;
        if (base == 0 && exponent < 0) {
            fail(at, "division by zero (0 to a negative power)");
            return 0;
        }
        if (base < 0 && exponent != std::floor(exponent)) {
            fail(at, "a negative number to a fractional power is undefined");
            return 0;
        }
        return checked(std::pow(base, exponent), at, "'^'");
    }

    double primary() {
        const char c = peek();
        const std::size_t at = pos_;
        if (c == '(') {
            ++pos_;
            if (!enter(at)) return 0;
            const double v = expression();
            --depth_;
            if (failed_ || !close(at)) return 0;
            return v;
        }
        if (isDigit(c) || c == '.') return number();
        if (isNameStart(c)) return name();
        unexpected();
        return 0;
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

    double name() {
        const std::size_t start = pos_;
        while (pos_ < text_.size() && isNameChar(text_[pos_])) ++pos_;
        const std::string_view word = text_.substr(start, pos_ - start);
        const FunctionInfo* function = findFunction(word);
        if (peek() == '(') {
            if (!function) {
                fail(start, "unknown function " + quoteToken(word) +
                                (word == "not" ? " (to negate, write '!')" : ""));
                return 0;
            }
            return call(*function, start);
        }
        if (const std::optional<double> v = variables_.find(word)) return *v;
        // A variable whose '/let' failed is known; where nothing is evaluated its value is not needed.
        if (variables_.isBroken(word) && skipping_ > 0) return 0;
        if (variables_.isBroken(word)) {
            if (!failed_) followOn_ = true;
            fail(start, "variable " + quoteToken(word) + " has no value: its '/let' failed", word.size());
            return 0;
        }
        if (function) {
            fail(start, quoteToken(word) + " is a function: write " + std::string(word) + "(...)",
                 word.size());
        } else {
            fail(start,
                 "unknown variable " + quoteToken(word) + (word == "not" ? " (to negate, write '!')" : ""),
                 word.size());
        }
        return 0;
    }

    double call(const FunctionInfo& f, std::size_t at) {
        const std::size_t open = pos_++;  // the '('
        if (!enter(open)) return 0;
        std::vector<double> args;
        if (peek() != ')') {
            for (;;) {
                // if(c, a, b) evaluates c, then only the branch it returns; the
                // other, and any argument past the third, is read but not evaluated.
                const bool skip = f.function == Function::If && !args.empty() &&
                                  (args.size() > 2 || (args[0] != 0) != (args.size() == 1));
                if (skip) ++skipping_;
                args.push_back(expression());
                if (skip) --skipping_;
                if (failed_) return 0;
                if (peek() != ',') break;
                ++pos_;
            }
        }
        --depth_;
        if (!close(open)) return 0;
        const int n = static_cast<int>(args.size());
        if (n < f.minArgs || (f.maxArgs >= 0 && n > f.maxArgs)) {
            std::string count =
                f.maxArgs < 0 ? "at least " + std::to_string(f.minArgs) : std::to_string(f.minArgs);
            const bool plural = f.minArgs != 1;
            fail(at, quoteToken(f.name) + " takes " + count + (plural ? " arguments" : " argument") +
                         ", got " + std::to_string(n) +
                         (f.function == Function::If ? " (write if(condition, value if true, value if false))"
                                                     : ""));
            return 0;
        }
        if (skipping_ > 0) return 0;  // not evaluated: no domain errors
        return apply(f, args, at);
    }

    double apply(const FunctionInfo& f, const std::vector<double>& args, std::size_t at) {
        const double x = args[0];
        const std::string call = std::string(f.name) + "(" + formatNumber(x) + ")";
        switch (f.function) {
            case Function::Sin:
                return sinDegrees(x);
            case Function::Cos:
                return cosDegrees(x);
            case Function::Tan: {
                const std::optional<double> t = tanDegrees(x);
                if (!t) fail(at, call + " is undefined (an odd multiple of 90 degrees)");
                return t.value_or(0);
            }
            case Function::Asin:
            case Function::Acos:
                if (x < -1 || x > 1) {
                    fail(at, call + " is undefined (the argument must be from -1 to 1)");
                    return 0;
                }
                return (f.function == Function::Asin ? std::asin(x) : std::acos(x)) * kDegreesPerRadian;
            case Function::Atan:
                return std::atan(x) * kDegreesPerRadian;
            case Function::Atan2:
                return std::atan2(x, args[1]) * kDegreesPerRadian;
            case Function::Sqrt:
                if (x < 0) {
                    fail(at, call + " is undefined (a negative number)");
                    return 0;
                }
                return std::sqrt(x);
            case Function::Abs:
                return std::fabs(x);
            case Function::Floor:
                return std::floor(x);
            case Function::Ceil:
                return std::ceil(x);
            case Function::Exp:
                return checked(std::exp(x), at, call);
            case Function::Log:
                if (x <= 0) {
                    fail(at, call + " is undefined (the argument must be > 0)");
                    return 0;
                }
                return std::log(x);
            case Function::Round:
                return std::round(x);  // halves away from zero
            case Function::If:
                return x != 0 ? args[1] : args[2];
            case Function::Min:
            case Function::Max: {
                double best = x;
                for (double a : args)
                    best = f.function == Function::Min ? std::min(best, a) : std::max(best, a);
                return best;
            }
        }
        return 0;
    }

    std::string_view text_;
    const Variables& variables_;
    std::size_t pos_ = 0;
    int depth_ = 0;
    /// > 0 while reading what is not evaluated (SPEC 10.7).
    int skipping_ = 0;
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
    for (const FunctionInfo& f : kFunctions) names.push_back(f.name);
    return names;
}

ExpressionResult evaluateExpression(std::string_view text, const Variables& variables) {
    return ExpressionParser(text, variables).whole();
}

ExpressionResult evaluateParenthesized(std::string_view text, const Variables& variables) {
    return ExpressionParser(text, variables).parenthesized();
}

std::optional<double> nearWhole(double value) {
    const double whole = std::round(value);
    if (std::fabs(value - whole) <= kWholeTolerance) return whole == 0 ? 0.0 : whole;
    return std::nullopt;
}

std::string formatNumber(double value) {
    std::array<char, 32> buffer{};
    const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    if (ec != std::errc()) return "?";
    return std::string(buffer.data(), end);
}

}  // namespace f2
