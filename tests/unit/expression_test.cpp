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

// Conditions (SPEC 10.7): comparisons, &&, ||, ! and if(c, a, b).

/// Checks that `text` fails at byte `offset` with exactly `message`.
void expectExactFailure(std::string_view text, std::size_t offset, std::string_view message,
                        const Variables& vars = Variables()) {
    SCOPED_TRACE(std::string(text));
    const ExpressionResult r = evaluateExpression(text, vars);
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.errorOffset, offset) << r.message;
    EXPECT_EQ(r.message, message);
}

TEST(Condition, ComparisonsGiveOneOrZero) {
    EXPECT_EQ(eval("1 == 1"), 1);
    EXPECT_EQ(eval("1 == 2"), 0);
    EXPECT_EQ(eval("1 != 2"), 1);
    EXPECT_EQ(eval("2 != 2"), 0);
    EXPECT_EQ(eval("1 < 2"), 1);
    EXPECT_EQ(eval("2 < 2"), 0);
    EXPECT_EQ(eval("2 <= 2"), 1);
    EXPECT_EQ(eval("3 <= 2"), 0);
    EXPECT_EQ(eval("3 > 2"), 1);
    EXPECT_EQ(eval("2 > 2"), 0);
    EXPECT_EQ(eval("2 >= 2"), 1);
    EXPECT_EQ(eval("1 >= 2"), 0);
    EXPECT_EQ(eval("-1<-2"), 0);  // '<' then unary minus
    EXPECT_EQ(eval("1<=-1"), 0);
    EXPECT_EQ(eval("-0 == 0"), 1);
    // Exact on doubles, as in every language: compare with a tolerance.
    EXPECT_EQ(eval("0.1 + 0.2 == 0.3"), 0);
    EXPECT_EQ(eval("abs(0.1 + 0.2 - 0.3) < 1e-9"), 1);
    EXPECT_FALSE(std::signbit(eval("-(1 < 0)")));  // -0 is 0, as for every result
}

TEST(Condition, LogicGivesOneOrZero) {
    EXPECT_EQ(eval("2 && 3"), 1);  // 1, not the operand (C, not JavaScript)
    EXPECT_EQ(eval("2 && 0"), 0);
    EXPECT_EQ(eval("0 || 0"), 0);
    EXPECT_EQ(eval("0 || -5"), 1);
    EXPECT_EQ(eval("0.5 || 0"), 1);
    EXPECT_EQ(eval("!0"), 1);
    EXPECT_EQ(eval("!7"), 0);
    EXPECT_EQ(eval("!-0.001"), 0);
    EXPECT_EQ(eval("!!3"), 1);
    EXPECT_EQ(eval("! 0"), 1);
}

TEST(Condition, Precedence) {
    EXPECT_EQ(eval("1 + 2 < 4"), 1);  // (1 + 2) < 4
    EXPECT_EQ(eval("1 + 2 < 3"), 0);
    EXPECT_EQ(eval("2 * 3 == 6"), 1);
    EXPECT_EQ(eval("1 < 2 == 1"), 1);      // (1 < 2) == 1: relations bind above equality
    EXPECT_EQ(eval("3 > 2 == 2 > 1"), 1);  // (3 > 2) == (2 > 1)
    EXPECT_EQ(eval("1 == 1 && 2 == 2"), 1);
    EXPECT_EQ(eval("2 > 1 && 3 > 2 || 0"), 1);
    EXPECT_EQ(eval("1 || 0 && 0"), 1);  // 1 || (0 && 0): && binds above ||
    EXPECT_EQ(eval("(1 || 0) && 0"), 0);
    EXPECT_EQ(eval("0 && 0 || 1"), 1);
    EXPECT_EQ(eval("1 || 1 || 0"), 1);  // left to right
    EXPECT_EQ(eval("1 && 1 && 0"), 0);
    // '!' is a unary prefix like '-': above * and +, below ^.
    EXPECT_EQ(eval("!0 + 1"), 2);
    EXPECT_EQ(eval("!1 + 1"), 1);
    EXPECT_EQ(eval("2 * !0"), 2);
    EXPECT_EQ(eval("!2^2"), 0);  // !(2^2), as -2^2 is -(2^2)
    EXPECT_EQ(eval("-!0"), -1);
    EXPECT_EQ(eval("!-1"), 0);
    EXPECT_EQ(eval("2^!0"), 2);
    EXPECT_EQ(eval("!1 == 0"), 1);  // (!1) == 0, as in C
    EXPECT_EQ(eval("!(1 == 0)"), 1);
    EXPECT_EQ(eval("-1 < 0 == !0"), 1);
}

TEST(Condition, AndOrShortCircuit) {
    EXPECT_EQ(eval("0 && 1/0"), 0);
    EXPECT_EQ(eval("1 || 1/0"), 1);
    EXPECT_EQ(eval("0 && sqrt(-1) || 1"), 1);
    EXPECT_EQ(eval("0 && log(0) && 1 % 0"), 0);
    EXPECT_EQ(eval("1 || 10^400"), 1);
    EXPECT_EQ(eval("1 || (-8)^0.5 + exp(1000) * 0^-1 + tan(90)"), 1);
    expectExactFailure("1 && 1/0", 6, "division by zero");
    expectExactFailure("0 || 1/0", 6, "division by zero");
    // What is not evaluated is still read: syntax, names and argument counts.
    expectExactFailure("0 && q", 5, "unknown variable 'q'");
    expectExactFailure("1 || foo(1)", 5, "unknown function 'foo'");
    expectExactFailure("0 && sqrt(1, 2)", 5, "'sqrt' takes 1 argument, got 2");
    expectExactFailure("0 && (1 +", 9, "the expression ends too early");
    expectExactFailure("1 || 1e400", 5, "number '1e400' is out of range");
    expectExactFailure("0 && 1 < 2 < 3", 11,
                       "comparisons do not chain: to test both, write 'a < b && b < c'; otherwise put the "
                       "first in parentheses");
}

TEST(Condition, IfEvaluatesOnlyTheBranchItReturns) {
    EXPECT_EQ(eval("if(1, 2, 3)"), 2);
    EXPECT_EQ(eval("if(0, 2, 3)"), 3);
    EXPECT_EQ(eval("if(-0.5, 2, 3)"), 2);  // any value but 0 is true
    EXPECT_EQ(eval("if(1, 2, 1/0)"), 2);
    EXPECT_EQ(eval("if(0, 1/0, 3)"), 3);
    EXPECT_EQ(eval("if(0, sqrt(-1), if(1, 4, log(0)))"), 4);
    EXPECT_EQ(eval("if(1 < 2 && 2 < 3, 10, 20) + 1"), 11);
    EXPECT_EQ(eval("if(0, 1, 2) * if(1, 3, 4)"), 6);
    EXPECT_EQ(eval("0 && if(1, 1/0, 1/0)"), 0);  // nothing evaluated inside either
    EXPECT_EQ(eval("if( 1 , -2 , 3 )"), -2);
    EXPECT_EQ(eval("max(1 < 2, 0.5)"), 1);  // any argument may be a condition
    Variables v;
    v.set("k", 2);
    EXPECT_EQ(eval("if(k == 2, 10, 20)", v), 10);
    EXPECT_EQ(eval("if(k != 2, 10, 20)", v), 20);
    // The condition is evaluated; the branch returned is too.
    expectExactFailure("if(1/0, 1, 2)", 4, "division by zero");
    expectExactFailure("if(1, 1/0, 2)", 7, "division by zero");
    expectExactFailure("if(0, 1, 2/0)", 10, "division by zero");
    // The other branch is read: a typo there is an error, a division by zero is not.
    expectExactFailure("if(1, 2, q)", 9, "unknown variable 'q'");
    expectExactFailure("if(0, q, 2)", 6, "unknown variable 'q'");
    expectExactFailure("if(1, 2, 3 +)", 12, "unexpected ')' in the expression");
    // A variable whose /let failed is known: needed, it fails silently (reported at its /let).
    v.markBroken("b");
    EXPECT_EQ(eval("if(1, 2, b)", v), 2);
    EXPECT_EQ(eval("0 && b", v), 0);
    const ExpressionResult taken = evaluateExpression("if(0, 2, b)", v);
    EXPECT_FALSE(taken.ok);
    EXPECT_TRUE(taken.followOn);
}

TEST(Condition, IfTakesThreeArguments) {
    const std::string_view hint = " (write if(condition, value if true, value if false))";
    expectExactFailure("if(1, 2)", 0, "'if' takes 3 arguments, got 2" + std::string(hint));
    expectExactFailure("2 * if(0, 1, 2, 3)", 4, "'if' takes 3 arguments, got 4" + std::string(hint));
    expectExactFailure("1 + if()", 4, "'if' takes 3 arguments, got 0" + std::string(hint));
    expectExactFailure("if(1)", 0, "'if' takes 3 arguments, got 1" + std::string(hint));
    // Not evaluated, still counted.
    expectExactFailure("0 && if(1, 2)", 5, "'if' takes 3 arguments, got 2" + std::string(hint));
    expectExactFailure("1 + if", 4, "'if' is a function: write if(...)");
    // A variable may still be called if: no scene valid before changes meaning.
    Variables v;
    v.set("if", 4);
    EXPECT_EQ(eval("if + if(1, 2, 3)", v), 6);
}

TEST(Condition, MistakesThatTeach) {
    Variables v;
    v.set("i", 3);
    expectExactFailure("i = 3", 2,
                       "'=' is not an operator: to compare, write '=='; to set a variable, use /let", v);
    expectExactFailure("if(i=3, 1, 2)", 4,
                       "'=' is not an operator: to compare, write '=='; to set a variable, use /let", v);
    expectExactFailure("1 & 2", 2, "'&' is not an operator: for 'and', write '&&'");
    expectExactFailure("1 | 2", 2, "'|' is not an operator: for 'or', write '||'");
    expectExactFailure("1 < 2 < 3", 6,
                       "comparisons do not chain: to test both, write 'a < b && b < c'; otherwise put the "
                       "first in parentheses");
    expectExactFailure("3 >= 2 > 1", 7,
                       "comparisons do not chain: to test both, write 'a >= b && b > c'; otherwise put the "
                       "first in parentheses");
    expectExactFailure("1 == 1 != 0", 7,
                       "comparisons do not chain: to test both, write 'a == b && b != c'; otherwise put the "
                       "first in parentheses");
    EXPECT_EQ(eval("(1 < 2) < 3"), 1);  // parentheses say what is meant
    expectExactFailure("1 === 1", 2, "'===' is not an operator: write '=='");
    expectExactFailure("1 !== 1", 2, "'!==' is not an operator: write '!='");
    expectExactFailure("1 <> 2", 2, "'<>' is not an operator: to test that two values differ, write '!='");
    expectExactFailure("1 => 2", 2, "'=>' is not an operator: write '>='");
    expectExactFailure("1 =< 2", 2, "'=<' is not an operator: write '<='");
    expectExactFailure("1 ? 2 : 3", 2,
                       "unexpected '?' in the expression: for a choice, write if(condition, a, b)");
    expectExactFailure("1 and 0", 2, "unexpected 'and' in the expression: for 'and', write '&&'");
    expectExactFailure("1 or 0", 2, "unexpected 'or' in the expression: for 'or', write '||'");
    expectExactFailure("not 1", 0, "unknown variable 'not' (to negate, write '!')");
    expectExactFailure("not(1)", 0, "unknown function 'not' (to negate, write '!')");
    // Two-character operators are quoted whole where an operand should be.
    expectExactFailure("== 1", 0, "unexpected '==' in the expression");
    expectExactFailure("1 + != 2", 4, "unexpected '!=' in the expression");
    expectExactFailure("1 &&", 4, "the expression ends too early");
    expectExactFailure("!", 1, "the expression ends too early");
    expectExactFailure("1 !", 2, "unexpected '!' in the expression");
}

TEST(Condition, NestingIsStillBounded) {
    std::string nots(100000, '!');
    const ExpressionResult r = evaluateExpression(nots + "0", Variables());
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.errorOffset, static_cast<std::size_t>(kMaxExpressionDepth));
    std::string ifs;
    for (int i = 0; i < 1000; ++i) ifs += "if(1, ";
    EXPECT_FALSE(evaluateExpression(ifs + "1", Variables()).ok);
    std::string fine;
    for (int i = 0; i < 200; ++i) fine += "if(0, 1/0, ";
    fine += "7";
    for (int i = 0; i < 200; ++i) fine += ")";
    EXPECT_EQ(eval(fine), 7);
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
