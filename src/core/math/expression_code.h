#pragma once
/// The arithmetic of the scene language's expressions (SPEC 9.4, 10.7) and
/// their compiled form: a small stack program that a `/drive` runs every
/// frame (SPEC 10.7). The parser (parse/expression.h) folds what is constant
/// with the same operations, so a compiled expression and the text evaluator
/// give the same bits. Below both the parser and the animation: neither
/// depends on the other.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace f2 {

/// `value` in the shortest decimal form that reads back as the same double
/// (parse/expression.h's formatNumber).
std::string shortestDecimal(double value);

/// The functions of expressions, in their table's order (expressionFunctions).
enum class ExprFunction : std::uint8_t {
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

struct ExprFunctionInfo {
    std::string_view name;
    ExprFunction function;
    int minArgs;
    int maxArgs;  ///< -1: any number
};

/// Every function, in ExprFunction order.
std::span<const ExprFunctionInfo> expressionFunctions();
/// The function named `name`, or nullptr.
const ExprFunctionInfo* findExpressionFunction(std::string_view name);

/// What a step of an expression can run into (SPEC 9.4).
enum class ExprProblem : std::uint8_t {
    None,
    NotFinite,
    DivisionByZero,
    RemainderByZero,
    ZeroToNegativePower,
    NegativeToFractionalPower,
    Undefined,  ///< a function outside its domain: tan(90), sqrt(-1), log(0), asin(2)
};

/// One operation's value, or its problem.
struct ExprStep {
    double value = 0;
    ExprProblem problem = ExprProblem::None;
};

/// The operations of a compiled expression.
enum class ExprOp : std::uint8_t {
    Push,  ///< the instruction's number
    Load,  ///< input `index`
    Neg,
    Not,
    ToBool,  ///< 1 if not 0, else 0
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Pow,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    Call,     ///< function `function` of the top `index` values
    AndJump,  ///< pops a; if a is 0, pushes 0 and skips `index` instructions
    OrJump,   ///< pops a; if a is not 0, pushes 1 and skips `index` instructions
    IfJump,   ///< pops c; if c is 0, skips `index` instructions (to the else branch)
    Jump,     ///< skips `index` instructions
};

/// `a op b` for the binary operators (Add … Ge), as the evaluator does it.
ExprStep applyOperator(ExprOp op, double a, double b);
/// `f(args)` for every function but `if` (whose branches are the caller's).
ExprStep applyFunction(ExprFunction f, std::span<const double> args);
/// The message of a problem of operator `op` ("division by zero", "the
/// result of '*' is not finite").
std::string operatorProblemText(ExprOp op, ExprProblem problem);
/// The message of a problem of `f` whose first argument is `x` ("sqrt(-1) is
/// undefined (a negative number)").
std::string functionProblemText(ExprFunction f, double x, ExprProblem problem);

struct ExprInstruction {
    ExprOp op = ExprOp::Push;
    ExprFunction function = ExprFunction::Sin;  ///< Call
    /// Load: input; Call: argument count; jumps: how far; a binary operator:
    /// 1 when its right operand is `number` (not on the stack).
    std::uint32_t index = 0;
    std::uint32_t offset = 0;  ///< where in the text, for a problem's message
    double number = 0;         ///< Push, and a binary operator's constant
};

/// Where and why an evaluation failed.
struct ExpressionFailure {
    std::size_t offset = 0;  ///< byte offset in the expression's text
    std::string message;
};

/// One of the codes that ExpressionCode::runLanes runs side by side.
struct ExprLane {
    const ExprInstruction* code;
    std::span<const double> inputs;
};

/// A compiled expression: a constant, or a program over inputs given at
/// each evaluation (a drive's frame and time).
class ExpressionCode {
   public:
    ExpressionCode() = default;
    static ExpressionCode constant(double value);
    explicit ExpressionCode(std::vector<ExprInstruction> code);

    bool isConstant() const { return code_.empty(); }
    /// The value with `inputs` (Load's indices), or NaN and, when `failure`
    /// is given, what failed. -0 gives 0, as the text evaluator does.
    double evaluate(std::span<const double> inputs, ExpressionFailure* failure = nullptr) const;
    std::span<const ExprInstruction> instructions() const { return code_; }
    std::size_t stackSize() const { return stackSize_; }
    /// evaluate() for `code` (not empty) that needs `stackSize` values of stack.
    static double run(std::span<const ExprInstruction> code, std::size_t stackSize,
                      std::span<const double> inputs, ExpressionFailure* failure);

    /// Most lanes and deepest stack of runLanes.
    static constexpr std::size_t kMaxLanes = 8, kLaneStack = 8;
    /// Whether `code` can run in lanes: no jumps, a stack of kLaneStack at most.
    static bool runsInLanes(std::span<const ExprInstruction> code, std::size_t stackSize);
    /// Whether two codes that run in lanes can run side by side: the same
    /// operations on the same stack slots (numbers, functions and inputs may
    /// differ: `x + 20*sin(time*90)` and `-40 + 15*cos(frame*7.5)` may).
    static bool sameShape(std::span<const ExprInstruction> a, std::span<const ExprInstruction> b);
    /// run() without a failure of up to kMaxLanes codes of `length`
    /// instructions and the same shape, side by side: values[l] is lane l's.
    /// Each instruction is dispatched once for all lanes; their sines and
    /// cosines are taken together (trigDegreesBatch), other functions' calls
    /// back to back.
    static void runLanes(std::span<const ExprLane> lanes, std::size_t length, double* values);

   private:
    std::vector<ExprInstruction> code_;
    double constant_ = 0;
    std::size_t stackSize_ = 0;
};

}  // namespace f2
