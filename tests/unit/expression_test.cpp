// Expressions of the scene language (SPEC 9.4): operators, precedence,
// functions in degrees, and every failure with the offset it points at.
#include "core/parse/expression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace f2 {
namespace {

double eval(std::string_view text, const Variables& vars = Variables()) {
    const ExpressionResult r = evaluateExpression(text, vars);
    EXPECT_TRUE(r.ok) << text << ": " << r.message;
    return r.value;
}

/// Checks that `text` fails at byte `offset` with a message containing `what`.
void expectFailure(std::string_view text, std::size_t offset, std::string_view what) {
    SCOPED_TRACE(std::string(text));
    const ExpressionResult r = evaluateExpression(text, Variables());
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.errorOffset, offset) << r.message;
    EXPECT_NE(r.message.find(what), std::string::npos) << "message: " << r.message << "\nexpected: " << what;
}

TEST(Expression, OperatorsAndPrecedence) {
    EXPECT_EQ(eval("1 + 2 * 3"), 7);
    EXPECT_EQ(eval("(1 + 2) * 3"), 9);
    EXPECT_EQ(eval("10 - 4 - 3"), 3);  // left-associative
    EXPECT_EQ(eval("2 * 3 / 4"), 1.5);
    EXPECT_EQ(eval("1e3 + .5"), 1000.5);
    EXPECT_EQ(eval("2E-1*10"), 2);
}

TEST(Expression, PowerIsRightAssociativeAndAboveUnaryMinus) {
    EXPECT_EQ(eval("-2^2"), -4);
    EXPECT_EQ(eval("(-2)^2"), 4);
    EXPECT_EQ(eval("2^3^2"), 512);
    EXPECT_EQ(eval("2^-1"), 0.5);
    EXPECT_EQ(eval("--3"), 3);
    EXPECT_EQ(eval("+3"), 3);
    EXPECT_EQ(eval("2*-3"), -6);
}

TEST(Expression, RemainderHasTheSignOfTheDivisor) {
    EXPECT_EQ(eval("7 % 3"), 1);
    EXPECT_EQ(eval("7 % -3"), -2);
    EXPECT_EQ(eval("-7 % 3"), 2);
    EXPECT_EQ(eval("-7 % -3"), -1);
    EXPECT_EQ(eval("6 % 3"), 0);
    EXPECT_EQ(eval("7.5 % 2"), 1.5);
}

TEST(Expression, TrigonometryInDegrees) {
    EXPECT_EQ(eval("sin(90)"), 1);
    EXPECT_EQ(eval("sin(180)"), 0);
    EXPECT_EQ(eval("sin(-90)"), -1);
    EXPECT_EQ(eval("cos(90)"), 0);
    EXPECT_EQ(eval("cos(180)"), -1);
    EXPECT_EQ(eval("cos(720)"), 1);
    EXPECT_EQ(eval("tan(45)"), 1);
    EXPECT_EQ(eval("tan(-45)"), -1);
    EXPECT_EQ(eval("tan(180)"), 0);
    EXPECT_NEAR(eval("sin(30)"), 0.5, 1e-15);
    EXPECT_NEAR(eval("tan(60)"), std::sqrt(3.0), 1e-14);
    EXPECT_NEAR(eval("atan2(1, -1)"), 135, 1e-12);
    EXPECT_NEAR(eval("atan2(-1, -1)"), -135, 1e-12);
    EXPECT_NEAR(eval("asin(0.5)"), 30, 1e-12);
    EXPECT_NEAR(eval("acos(-1)"), 180, 1e-12);
    EXPECT_NEAR(eval("atan(1)"), 45, 1e-12);
}

TEST(Expression, OtherFunctions) {
    EXPECT_EQ(eval("sqrt(16)"), 4);
    EXPECT_EQ(eval("abs(-2.5)"), 2.5);
    EXPECT_EQ(eval("floor(-1.5)"), -2);
    EXPECT_EQ(eval("ceil(-1.5)"), -1);
    EXPECT_EQ(eval("round(2.5)"), 3);
    EXPECT_EQ(eval("round(-2.5)"), -3);  // halves away from zero
    EXPECT_EQ(eval("round(0.49)"), 0);
    EXPECT_EQ(eval("exp(0)"), 1);
    EXPECT_NEAR(eval("log(exp(2))"), 2, 1e-15);
    EXPECT_EQ(eval("min(3)"), 3);
    EXPECT_EQ(eval("min(3, -1, 2)"), -1);
    EXPECT_EQ(eval("max(3, -1, 2)"), 3);
    EXPECT_EQ(eval("max(1, min(5, 4))"), 4);
}

TEST(Expression, VariablesAndPi) {
    Variables v;
    EXPECT_NEAR(eval("pi", v), 3.14159265358979, 1e-14);
    v.set("i", 2);
    v.set("r_1", 0.5);
    EXPECT_EQ(eval("i + 1", v), 3);
    EXPECT_EQ(eval("i * r_1", v), 1);
    v.set("i", 5);
    EXPECT_EQ(eval("i", v), 5);
    v.erase("i");
    EXPECT_FALSE(evaluateExpression("i", v).ok);
    EXPECT_TRUE(Variables::isPredefined("pi"));
    EXPECT_FALSE(Variables::isPredefined("x"));
}

TEST(Expression, ParenthesizedArgument) {
    const Variables v;
    const ExpressionResult r = evaluateParenthesized("( 1 + 2 )", v);
    EXPECT_TRUE(r.ok);
    EXPECT_EQ(r.value, 3);
    const ExpressionResult trailing = evaluateParenthesized("(1)+(2)", v);
    EXPECT_FALSE(trailing.ok);
    EXPECT_EQ(trailing.errorOffset, 3u);
    EXPECT_NE(trailing.message.find("after the ')'"), std::string::npos) << trailing.message;
    const ExpressionResult open = evaluateParenthesized("(1 + (2)", v);
    EXPECT_FALSE(open.ok);
    EXPECT_EQ(open.errorOffset, 0u);
    EXPECT_NE(open.message.find("no matching ')'"), std::string::npos) << open.message;
}

TEST(Expression, EveryFailureNamesItsPlace) {
    expectFailure("1 + x", 4, "unknown variable 'x'");
    expectFailure("foo(1)", 0, "unknown function 'foo'");
    expectFailure("2 * sin", 4, "'sin' is a function");
    expectFailure("1 / 0", 2, "division by zero");
    expectFailure("1 % (2 - 2)", 2, "remainder of a division by zero");
    expectFailure("0 ^ -1", 2, "division by zero");
    expectFailure("(-8) ^ 0.5", 5, "fractional power");
    expectFailure("sqrt(-1)", 0, "sqrt(-1) is undefined");
    expectFailure("1 + log(0)", 4, "log(0) is undefined");
    expectFailure("asin(2)", 0, "asin(2) is undefined");
    expectFailure("acos(-1.5)", 0, "acos(-1.5) is undefined");
    expectFailure("tan(90)", 0, "tan(90) is undefined");
    expectFailure("tan(-270)", 0, "is undefined");
    expectFailure("exp(1000)", 0, "exp(1000) is not finite");
    expectFailure("exp(700) * exp(700)", 9, "the result of '*' is not finite");
    expectFailure("10 ^ 400", 3, "the result of '^' is not finite");
    expectFailure("atan2(1)", 0, "'atan2' takes 2 arguments, got 1");
    expectFailure("sqrt(1, 2)", 0, "'sqrt' takes 1 argument, got 2");
    expectFailure("min()", 0, "'min' takes at least 1 argument, got 0");
    expectFailure("1 +", 3, "ends too early");
    expectFailure("1 2", 2, "unexpected '2'");
    expectFailure("1 + )", 4, "unexpected ')'");
    expectFailure("1..2", 0, "invalid number '1..2'");
    expectFailure("1e400", 0, "number '1e400' is out of range");
    expectFailure("(1", 0, "no matching ')'");
    expectFailure("1 $ 2", 2, "unexpected '$'");
}

TEST(Expression, DeepNestingIsAnErrorNotACrash) {
    const std::string deep = std::string(100000, '(') + "1" + std::string(100000, ')');
    const ExpressionResult r = evaluateExpression(deep, Variables());
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.errorOffset, static_cast<std::size_t>(kMaxExpressionDepth));
    EXPECT_NE(r.message.find("nested more than 256 levels"), std::string::npos) << r.message;
    EXPECT_FALSE(evaluateExpression(std::string(100000, '-') + "1", Variables()).ok);
    std::string powers = "2";
    for (int i = 0; i < 50000; ++i) powers += "^1";
    EXPECT_FALSE(evaluateExpression(powers, Variables()).ok);
    // Just inside the limit still works.
    const std::string fine = std::string(200, '(') + "1" + std::string(200, ')');
    EXPECT_EQ(eval(fine), 1);
}

TEST(Expression, WholeNumbersWithinOneMillionth) {
    EXPECT_EQ(nearWhole(3.0000004), 3.0);
    EXPECT_EQ(nearWhole(-2.9999996), -3.0);
    EXPECT_EQ(nearWhole(3.00001), std::nullopt);
    EXPECT_EQ(nearWhole(0.5), std::nullopt);
    EXPECT_FALSE(std::signbit(*nearWhole(-0.0000001)));
}

TEST(Expression, FormatsTheShortestRoundTrip) {
    EXPECT_EQ(formatNumber(3), "3");
    EXPECT_EQ(formatNumber(-0.25), "-0.25");
    EXPECT_EQ(formatNumber(0.1 + 0.2), "0.30000000000000004");
}

}  // namespace
}  // namespace f2
