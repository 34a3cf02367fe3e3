#pragma once
/// Arithmetic expressions of the scene language (SPEC 9.4): `( … )` wherever a
/// number is expected and `{ … }` inside names, over numbers, variables, the
/// operators + - * / % ^ and a few functions of degrees; and conditions
/// (SPEC 10.7): comparisons, && || ! and if(c, a, b), each giving 1 or 0.
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/math/expression_code.h"

namespace f2 {

/// Parentheses, unary signs and powers may nest this deep; deeper is an error
/// rather than a stack overflow **(choice)**.
inline constexpr int kMaxExpressionDepth = 256;

/// The variables every scene has, which cannot be redefined.
inline constexpr std::array<std::string_view, 1> kPredefinedVariables = {"pi"};

/// The variables of a scene: `/let` and loop variables, plus `pi`.
class Variables {
   public:
    Variables();
    /// The value of `name`, or nullopt if it is not defined.
    std::optional<double> find(std::string_view name) const;
    /// Defines or redefines `name` (the caller checks isPredefined first).
    void set(std::string_view name, double value);
    void erase(std::string_view name);
    /// The `/let` that would have defined `name` failed (its error is
    /// reported): until it is set, a use of it fails as a follow-on, which is
    /// not reported a second time.
    void markBroken(std::string_view name);
    bool isBroken(std::string_view name) const;
    /// `pi` cannot be redefined, by `/let` or as a loop variable.
    static bool isPredefined(std::string_view name);

   private:
    struct Hash {
        using is_transparent = void;
        std::size_t operator()(std::string_view s) const noexcept { return std::hash<std::string_view>{}(s); }
    };
    std::unordered_map<std::string, double, Hash, std::equal_to<>> values_;
    std::unordered_set<std::string, Hash, std::equal_to<>> broken_;
};

/// The value of an expression, or the first problem in it and where it is.
struct ExpressionResult {
    bool ok = false;
    double value = 0;
    std::size_t errorOffset = 0;  ///< byte offset of the problem inside the text
    std::size_t errorLength = 0;  ///< bytes it covers there (a name's); 0: a point
    std::string message;
    /// The problem is a variable whose `/let` failed: already reported there.
    bool followOn = false;
};

/// Evaluates a whole expression (`i + 1`, the inside of `{ … }`). Every
/// failure of SPEC 9.4 is an error: unknown variable or function, division by
/// zero, a result that is not finite, a domain error. What is not evaluated
/// (the right side of a decided `&&` or `||`, the branch `if` does not
/// return) is still checked for syntax, names and argument counts, but a
/// value's failure there (division by zero, domain) is none (SPEC 10.7).
ExpressionResult evaluateExpression(std::string_view text, const Variables& variables);

/// Evaluates a `( … )` argument: `text` starts with '(' and must end at its
/// matching ')'.
ExpressionResult evaluateParenthesized(std::string_view text, const Variables& variables);

/// A `( … )` argument compiled (SPEC 10.7): `result` as evaluateParenthesized
/// gives it (its value 0 when the expression depends on an input), and the
/// code that computes it from the inputs' values.
struct CompiledExpression {
    ExpressionResult result;
    ExpressionCode code;
};

/// Compiles a `( … )` argument in which each name of `inputs` (a drive's
/// `frame` and `time`) stands for the value given at that index at each
/// evaluation; every other variable takes its value now. What does not
/// depend on an input is computed now, with its errors; what does is left to
/// ExpressionCode::evaluate, whose problems are those of SPEC 9.4 too.
CompiledExpression compileParenthesized(std::string_view text, const Variables& variables,
                                        std::span<const std::string_view> inputs);

/// The functions of expressions ("sin", …, "max"), in their table's order:
/// completion and the generated grammar list these.
std::vector<std::string_view> expressionFunctionNames();

/// `value` in the shortest decimal form that reads back as the same double.
inline std::string formatNumber(double value) { return shortestDecimal(value); }

/// A whole number within 1e-6 of `value` (SPEC 9.4 integer fields), or nullopt.
std::optional<double> nearWhole(double value);

}  // namespace f2
