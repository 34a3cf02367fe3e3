#include "core/math/expression_code.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "core/math/trig_degrees.h"
#include "core/util/decimal_text.h"

namespace f2 {

namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

constexpr std::array<ExprFunctionInfo, 17> kFunctions = {{
    {"sin", ExprFunction::Sin, 1, 1},
    {"cos", ExprFunction::Cos, 1, 1},
    {"tan", ExprFunction::Tan, 1, 1},
    {"asin", ExprFunction::Asin, 1, 1},
    {"acos", ExprFunction::Acos, 1, 1},
    {"atan", ExprFunction::Atan, 1, 1},
    {"atan2", ExprFunction::Atan2, 2, 2},
    {"sqrt", ExprFunction::Sqrt, 1, 1},
    {"abs", ExprFunction::Abs, 1, 1},
    {"floor", ExprFunction::Floor, 1, 1},
    {"ceil", ExprFunction::Ceil, 1, 1},
    {"exp", ExprFunction::Exp, 1, 1},
    {"log", ExprFunction::Log, 1, 1},
    {"round", ExprFunction::Round, 1, 1},
    {"min", ExprFunction::Min, 1, -1},
    {"max", ExprFunction::Max, 1, -1},
    {"if", ExprFunction::If, 3, 3},  // SPEC 10.7: evaluates only the branch it returns
}};

/// A value that must be finite, as every step's is.
ExprStep finite(double v) { return {v, std::isfinite(v) ? ExprProblem::None : ExprProblem::NotFinite}; }

constexpr ExprStep kUndefined{0, ExprProblem::Undefined};

}  // namespace

std::string shortestDecimal(double value) { return shortestText(value); }

std::span<const ExprFunctionInfo> expressionFunctions() { return kFunctions; }

const ExprFunctionInfo* findExpressionFunction(std::string_view name) {
    for (const ExprFunctionInfo& f : kFunctions) {
        if (f.name == name) return &f;
    }
    return nullptr;
}

namespace {
// Inlined into ExpressionCode::run: a call per operation measured slower.
[[gnu::always_inline]] inline ExprStep operate(ExprOp op, double a, double b) {
    switch (op) {
        case ExprOp::Add:
            return finite(a + b);
        case ExprOp::Sub:
            return finite(a - b);
        case ExprOp::Mul:
            return finite(a * b);
        case ExprOp::Div:
            if (b == 0) return {0, ExprProblem::DivisionByZero};
            return finite(a / b);
        case ExprOp::Mod: {
            if (b == 0) return {0, ExprProblem::RemainderByZero};
            // The remainder takes the sign of the divisor: 7 % -3 = -2, -7 % 3 = 2.
            double r = std::fmod(a, b);
            if (r != 0 && ((r < 0) != (b < 0))) r += b;
            return {r};
        }
        case ExprOp::Pow:
            if (a == 0 && b < 0) return {0, ExprProblem::ZeroToNegativePower};
            if (a < 0 && b != std::floor(b)) return {0, ExprProblem::NegativeToFractionalPower};
            return finite(std::pow(a, b));
        case ExprOp::Eq:
            return {a == b ? 1.0 : 0.0};
        case ExprOp::Ne:
            return {a != b ? 1.0 : 0.0};
        case ExprOp::Lt:
            return {a < b ? 1.0 : 0.0};
        case ExprOp::Le:
            return {a <= b ? 1.0 : 0.0};
        case ExprOp::Gt:
            return {a > b ? 1.0 : 0.0};
        case ExprOp::Ge:
            return {a >= b ? 1.0 : 0.0};
        default:
            return {};
    }
}
}  // namespace

ExprStep applyOperator(ExprOp op, double a, double b) { return operate(op, a, b); }

namespace {
// Inlined into ExpressionCode::run, as operate().
[[gnu::always_inline]] inline ExprStep call(ExprFunction f, std::span<const double> args) {
    const double x = args[0];
    switch (f) {
        case ExprFunction::Sin:
            return {sinDegrees(x)};
        case ExprFunction::Cos:
            return {cosDegrees(x)};
        case ExprFunction::Tan: {
            const std::optional<double> t = tanDegrees(x);
            return t ? ExprStep{*t} : kUndefined;
        }
        case ExprFunction::Asin:
        case ExprFunction::Acos:
            if (x < -1 || x > 1) return kUndefined;
            return {(f == ExprFunction::Asin ? std::asin(x) : std::acos(x)) * kDegreesPerRadian};
        case ExprFunction::Atan:
            return {std::atan(x) * kDegreesPerRadian};
        case ExprFunction::Atan2:
            return {std::atan2(x, args[1]) * kDegreesPerRadian};
        case ExprFunction::Sqrt:
            if (x < 0) return kUndefined;
            return {std::sqrt(x)};
        case ExprFunction::Abs:
            return {std::fabs(x)};
        case ExprFunction::Floor:
            return {std::floor(x)};
        case ExprFunction::Ceil:
            return {std::ceil(x)};
        case ExprFunction::Exp:
            return finite(std::exp(x));
        case ExprFunction::Log:
            if (x <= 0) return kUndefined;
            return {std::log(x)};
        case ExprFunction::Round:
            return {std::round(x)};  // halves away from zero
        case ExprFunction::If:
            return {x != 0 ? args[1] : args[2]};
        case ExprFunction::Min:
        case ExprFunction::Max: {
            double best = x;
            for (double a : args) best = f == ExprFunction::Min ? std::min(best, a) : std::max(best, a);
            return {best};
        }
    }
    return {};
}
}  // namespace

ExprStep applyFunction(ExprFunction f, std::span<const double> args) { return call(f, args); }

std::string operatorProblemText(ExprOp op, ExprProblem problem) {
    switch (problem) {
        case ExprProblem::DivisionByZero:
            return "division by zero";
        case ExprProblem::RemainderByZero:
            return "remainder of a division by zero";
        case ExprProblem::ZeroToNegativePower:
            return "division by zero (0 to a negative power)";
        case ExprProblem::NegativeToFractionalPower:
            return "a negative number to a fractional power is undefined";
        default:
            break;
    }
    constexpr std::string_view kSymbols = "+-*/%^";
    const std::size_t k = std::size_t(op) - std::size_t(ExprOp::Add);
    const std::string symbol = k < kSymbols.size() ? std::string(1, kSymbols[k]) : "?";
    return "the result of '" + symbol + "' is not finite";
}

std::string functionProblemText(ExprFunction f, double x, ExprProblem problem) {
    const std::string call = std::string(kFunctions[std::size_t(f)].name) + "(" + shortestDecimal(x) + ")";
    if (problem != ExprProblem::Undefined) return "the result of " + call + " is not finite";
    switch (f) {
        case ExprFunction::Tan:
            return call + " is undefined (an odd multiple of 90 degrees)";
        case ExprFunction::Asin:
        case ExprFunction::Acos:
            return call + " is undefined (the argument must be from -1 to 1)";
        case ExprFunction::Sqrt:
            return call + " is undefined (a negative number)";
        default:
            return call + " is undefined (the argument must be > 0)";
    }
}

ExpressionCode ExpressionCode::constant(double value) {
    ExpressionCode c;
    c.constant_ = value == 0 ? 0.0 : value;
    return c;
}

ExpressionCode::ExpressionCode(std::vector<ExprInstruction> code) : code_(std::move(code)) {
    // The deepest the stack gets along the code read in order: at an IfJump's
    // Jump the then-branch's value is still counted, so this is an upper bound.
    std::size_t depth = 0;
    for (const ExprInstruction& i : code_) {
        switch (i.op) {
            case ExprOp::Push:
            case ExprOp::Load:
                ++depth;
                break;
            case ExprOp::Call:
                depth -= i.index - 1;
                break;
            case ExprOp::AndJump:
            case ExprOp::OrJump:
            case ExprOp::IfJump:
                --depth;
                break;
            case ExprOp::Neg:
            case ExprOp::Not:
            case ExprOp::ToBool:
            case ExprOp::Jump:
                break;
            default:
                depth -= i.index == 0;  // a binary operator: two values to one, or one and its constant
        }
        stackSize_ = std::max(stackSize_, depth + 1);
    }
}

double ExpressionCode::evaluate(std::span<const double> inputs, ExpressionFailure* failure) const {
    if (code_.empty()) return constant_;
    return run(code_, stackSize_, inputs, failure);
}

double ExpressionCode::run(std::span<const ExprInstruction> code, std::size_t stackSize,
                           std::span<const double> inputs, ExpressionFailure* failure) {
    // Most expressions need a few slots: no allocation then.
    constexpr std::size_t kLocal = 32;
    std::array<double, kLocal> local;
    std::vector<double> heap;
    double* stack = local.data();
    if (stackSize > kLocal) {
        heap.resize(stackSize);
        stack = heap.data();
    }
    std::size_t top = 0;  // values on the stack
    const auto fail = [&](const ExprInstruction& i, std::string message) {
        if (failure) *failure = {i.offset, std::move(message)};
        return std::numeric_limits<double>::quiet_NaN();
    };
    const std::size_t size = code.size();
    for (std::size_t pc = 0; pc < size; ++pc) {
        const ExprInstruction& i = code[pc];
        switch (i.op) {
            case ExprOp::Push:
                stack[top++] = i.number;
                break;
            case ExprOp::Load:
                stack[top++] = inputs[i.index];
                break;
            case ExprOp::Neg:
                stack[top - 1] = -stack[top - 1];
                break;
            case ExprOp::Not:
                stack[top - 1] = stack[top - 1] == 0 ? 1 : 0;
                break;
            case ExprOp::ToBool:
                stack[top - 1] = stack[top - 1] != 0 ? 1 : 0;
                break;
            case ExprOp::Call: {
                top -= i.index;
                const ExprStep s = call(i.function, {stack + top, i.index});
                if (s.problem != ExprProblem::None)
                    return fail(i, functionProblemText(i.function, stack[top], s.problem));
                stack[top++] = s.value;
                break;
            }
            case ExprOp::AndJump:
                if (stack[top - 1] == 0) {
                    pc += i.index;  // leaves the 0 as the result
                } else {
                    --top;
                }
                break;
            case ExprOp::OrJump:
                if (stack[top - 1] != 0) {
                    stack[top - 1] = 1;
                    pc += i.index;
                } else {
                    --top;
                }
                break;
            case ExprOp::IfJump:
                if (stack[--top] == 0) pc += i.index;
                break;
            case ExprOp::Jump:
                pc += i.index;
                break;
            default: {
                const double b = i.index ? i.number : stack[--top];
                const ExprStep s = operate(i.op, stack[top - 1], b);
                if (s.problem != ExprProblem::None) return fail(i, operatorProblemText(i.op, s.problem));
                stack[top - 1] = s.value;
            }
        }
    }
    const double v = stack[0];
    if (!std::isfinite(v)) return fail(code.back(), "the value is not finite");
    return v == 0 ? 0.0 : v;
}

bool ExpressionCode::runsInLanes(std::span<const ExprInstruction> code, std::size_t stackSize) {
    if (code.empty() || stackSize > kLaneStack) return false;
    return std::none_of(code.begin(), code.end(), [](const ExprInstruction& i) {
        return i.op == ExprOp::AndJump || i.op == ExprOp::OrJump || i.op == ExprOp::IfJump ||
               i.op == ExprOp::Jump;
    });
}

bool ExpressionCode::sameShape(std::span<const ExprInstruction> a, std::span<const ExprInstruction> b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const ExprInstruction& x, const ExprInstruction& y) {
                          return x.op == y.op && (x.index == y.index || x.op == ExprOp::Load);
                      });
}

namespace {
using LaneStacks = std::array<std::array<double, ExpressionCode::kLaneStack>, ExpressionCode::kMaxLanes>;

/// Binary operator `op` at instruction `pc` of every lane: the switch of
/// operate() folds away, leaving one operation in the loop.
template <ExprOp op>
void operateInLanes(std::span<const ExprLane> lanes, std::size_t pc, std::size_t top, bool constant,
                    LaneStacks& stack, std::array<bool, ExpressionCode::kMaxLanes>& failed) {
    for (std::size_t l = 0; l < lanes.size(); ++l) {
        const double b = constant ? lanes[l].code[pc].number : stack[l][top];
        const ExprStep s = operate(op, stack[l][top - 1], b);
        failed[l] = failed[l] || s.problem != ExprProblem::None;
        stack[l][top - 1] = s.value;
    }
}

/// Whether instruction `pc` of every lane is sin or cos (they never fail).
bool sinesOrCosines(std::span<const ExprLane> lanes, std::size_t pc) {
    return std::all_of(lanes.begin(), lanes.end(), [pc](const ExprLane& lane) {
        return lane.code[pc].function == ExprFunction::Sin || lane.code[pc].function == ExprFunction::Cos;
    });
}
static_assert(ExpressionCode::kMaxLanes <= kTrigBatch);

using LaneOperator = void (*)(std::span<const ExprLane>, std::size_t, std::size_t, bool, LaneStacks&,
                              std::array<bool, ExpressionCode::kMaxLanes>&);
/// The binary operators Add … Ge in ExprOp order (jumps never run in lanes: runsInLanes).
constexpr std::array<LaneOperator, 12> kLaneOperators = {
    &operateInLanes<ExprOp::Add>, &operateInLanes<ExprOp::Sub>, &operateInLanes<ExprOp::Mul>,
    &operateInLanes<ExprOp::Div>, &operateInLanes<ExprOp::Mod>, &operateInLanes<ExprOp::Pow>,
    &operateInLanes<ExprOp::Eq>,  &operateInLanes<ExprOp::Ne>,  &operateInLanes<ExprOp::Lt>,
    &operateInLanes<ExprOp::Le>,  &operateInLanes<ExprOp::Gt>,  &operateInLanes<ExprOp::Ge>};
}  // namespace

void ExpressionCode::runLanes(std::span<const ExprLane> lanes, std::size_t length, double* values) {
    LaneStacks stack;
    std::array<bool, kMaxLanes> failed{};
    const std::size_t count = lanes.size();
    std::size_t top = 0;  // values on each lane's stack
    for (std::size_t pc = 0; pc < length; ++pc) {
        const ExprInstruction& shape = lanes[0].code[pc];
        switch (shape.op) {
            case ExprOp::Push:
                for (std::size_t l = 0; l < count; ++l) stack[l][top] = lanes[l].code[pc].number;
                ++top;
                break;
            case ExprOp::Load:
                for (std::size_t l = 0; l < count; ++l)
                    stack[l][top] = lanes[l].inputs[lanes[l].code[pc].index];
                ++top;
                break;
            case ExprOp::Neg:
                for (std::size_t l = 0; l < count; ++l) stack[l][top - 1] = -stack[l][top - 1];
                break;
            case ExprOp::Not:
                for (std::size_t l = 0; l < count; ++l) stack[l][top - 1] = stack[l][top - 1] == 0 ? 1 : 0;
                break;
            case ExprOp::ToBool:
                for (std::size_t l = 0; l < count; ++l) stack[l][top - 1] = stack[l][top - 1] != 0 ? 1 : 0;
                break;
            case ExprOp::Call:
                top -= shape.index;
                if (shape.index == 1 && sinesOrCosines(lanes, pc)) {
                    // A grid's drives: their sines and cosines side by side (SIMD).
                    std::array<double, kTrigBatch> degrees{}, cosine{}, out;
                    for (std::size_t l = 0; l < count; ++l) {
                        degrees[l] = stack[l][top];
                        cosine[l] = lanes[l].code[pc].function == ExprFunction::Cos ? 1 : 0;
                    }
                    trigDegreesBatch(degrees.data(), cosine.data(), out.data());
                    for (std::size_t l = 0; l < count; ++l) stack[l][top] = out[l];
                    ++top;
                    break;
                }
                for (std::size_t l = 0; l < count; ++l) {
                    const ExprStep s = call(lanes[l].code[pc].function, {&stack[l][top], shape.index});
                    failed[l] = failed[l] || s.problem != ExprProblem::None;
                    stack[l][top] = s.value;
                }
                ++top;
                break;
            default: {
                const bool constant = shape.index != 0;
                if (!constant) --top;
                const std::size_t k = std::size_t(shape.op) - std::size_t(ExprOp::Add);
                if (k < kLaneOperators.size()) kLaneOperators[k](lanes, pc, top, constant, stack, failed);
            }
        }
    }
    // As run() ends: a failed step or a value that is not finite gives NaN.
    for (std::size_t l = 0; l < count; ++l) {
        const double v = stack[l][0];
        values[l] = failed[l] || !std::isfinite(v) ? std::numeric_limits<double>::quiet_NaN()
                    : v == 0                       ? 0.0
                                                   : v;
    }
}

}  // namespace f2
