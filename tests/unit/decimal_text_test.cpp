// The portable decimal reader and writers (core/util/decimal_text.h), which
// the WebAssembly build uses, give the standard library's results exactly:
// here, where the standard library has floating-point from_chars/to_chars.
#include "core/util/decimal_text.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace f2 {
namespace {

/// Reads `text` both ways; any difference in end, error or bits is a failure.
void expectSameRead(const std::string& text) {
    const char* first = text.data();
    const char* last = first + text.size();
    double standard = 1234.5, ours = 1234.5;  // unchanged on an error
    const auto [stdPtr, stdEc] = std::from_chars(first, last, standard, std::chars_format::general);
    const DecimalRead read = portable::readDecimal(first, last, ours);
    EXPECT_EQ(read.ptr - first, stdPtr - first) << "'" << text << "'";
    EXPECT_EQ(int(read.ec), int(stdEc)) << "'" << text << "'";
    if (std::isnan(standard)) {
        EXPECT_TRUE(std::isnan(ours)) << "'" << text << "'";
        EXPECT_EQ(std::signbit(ours), std::signbit(standard)) << "'" << text << "'";
    } else {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(ours), std::bit_cast<std::uint64_t>(standard))
            << "'" << text << "': " << ours << " vs " << standard;
    }
}

template <class Number>
std::string standardShortest(Number value) {
    char buffer[64];
    return {buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr};
}

std::string standardGeneral(double value, int precision) {
    char buffer[64];
    return {buffer,
            std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, precision).ptr};
}

const std::vector<std::string> kEdgeTexts = {
    "",
    "-",
    "+1",
    ".",
    "-.",
    ".5",
    "5.",
    "-5.",
    "1.5",
    "-0",
    "0",
    "0.0",
    "-0.0",
    "00012",
    "0012.500",
    "1e",
    "1e+",
    "1e-",
    "1E5",
    "1e+5",
    "1e-5",
    "1e0001",
    "1.5x",
    "1,5",
    " 1",
    "0x10",
    "e5",
    "-e5",
    ".e5",
    "inf",
    "-inf",
    "INF",
    "Infinity",
    "-infinity",
    "infin",
    "nan",
    "-nan",
    "NaN",
    "nan(123)",
    "nan(abc_1)",
    "nan(",
    "nan(1",
    "nan()",
    "1e400",
    "-1e400",
    "1e-400",
    "-1e-400",
    "1e-310",
    "1e-320",
    "1e-323",
    "4.9406564584124654e-324",
    "2.4703282292062327e-324",
    "2.4703282292062328e-324",
    "3e-324",
    "1.7976931348623157e308",
    "1.7976931348623158e308",
    "1.7976931348623159e308",
    "1.797693134862316e308",
    "2.2250738585072011e-308",
    "2.2250738585072014e-308",
    "9007199254740993",
    "9007199254740992.5",
    "9007199254740993.0000000000000000000001",
    "0.1",
    "0.2",
    "0.3",
    "1e23",
    "8.589973e9",
    "1e9999999999999",
    "1e-9999999999999",
    "0e9999999999999",
    "123456789012345678901234567890",
    "3.4028234663852886e38",
    "0.000000000000000000000000000000000000000000000000000000000000000000001",
    "1.00000000000000011102230246251565404236316680908203125",  // halfway between 1 and the next double
    "1.00000000000000011102230246251565404236316680908203124",
    "1.00000000000000011102230246251565404236316680908203126",
};

TEST(DecimalText, ReadsEdgeCasesAsFromChars) {
    for (const std::string& text : kEdgeTexts) expectSameRead(text);
}

TEST(DecimalText, ReadsRandomDoublesTextsAsFromChars) {
    std::mt19937_64 random(25);
    for (int i = 0; i < 100000; ++i) {
        const double value = std::bit_cast<double>(random());
        if (!std::isfinite(value)) continue;
        expectSameRead(standardShortest(value));
        expectSameRead(standardGeneral(value, 17));
        expectSameRead(standardGeneral(value, int(random() % 17) + 1));
    }
}

TEST(DecimalText, ReadsRandomDigitStringsAsFromChars) {
    std::mt19937_64 random(7);
    for (int i = 0; i < 100000; ++i) {
        std::string text = random() % 4 == 0 ? "-" : "";
        const int digits = int(random() % 30) + 1;
        const int point = int(random() % std::uint64_t(digits + 2)) - 1;  // -1: none
        for (int d = 0; d < digits; ++d) {
            if (d == point) text += '.';
            text += char('0' + random() % 10);
        }
        if (random() % 2 == 0) text += "e" + std::to_string(int(random() % 700) - 350);
        expectSameRead(text);
    }
}

TEST(DecimalText, WritesShortestDoublesAsToChars) {
    std::mt19937_64 random(11);
    std::vector<double> values = {0.0,
                                  -0.0,
                                  1.0,
                                  -1.0,
                                  0.1,
                                  1e20,
                                  1e21,
                                  1e-4,
                                  1e-5,
                                  123456.0,
                                  1234567.0,
                                  0.001,
                                  5e-324,
                                  2.2250738585072014e-308,
                                  std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity(),
                                  9007199254740992.0,
                                  1e23,
                                  2e23};
    for (int e = -1074; e <= 1023; ++e) values.push_back(std::ldexp(1.0, e));  // the asymmetric neighbours
    for (int i = 0; i < 15000; ++i) {
        const double value = std::bit_cast<double>(random());
        if (!std::isnan(value)) values.push_back(value);
        values.push_back(double(random() % 100000) / double(1 + random() % 1000));
    }
    for (double value : values) EXPECT_EQ(portable::shortestText(value), standardShortest(value)) << value;
    EXPECT_EQ(portable::shortestText(std::numeric_limits<double>::quiet_NaN()),
              standardShortest(std::numeric_limits<double>::quiet_NaN()));
}

TEST(DecimalText, WritesShortestFloatsAsToChars) {
    std::mt19937 random(13);
    std::vector<float> values = {0.0f, -0.0f, 0.1f, 0.25f, 1e-45f, 3.4028235e38f, 1e10f, 16777216.0f, 0.3f};
    for (int e = -149; e <= 127; ++e) values.push_back(std::ldexp(1.0f, e));
    for (int i = 0; i < 30000; ++i) {
        const float value = std::bit_cast<float>(std::uint32_t(random()));
        if (!std::isnan(value)) values.push_back(value);
        values.push_back(float(random() % 1000) / 100.0f);  // what easing curves hold
    }
    for (float value : values) EXPECT_EQ(portable::shortestText(value), standardShortest(value)) << value;
}

TEST(DecimalText, WritesGeneralPrecisionAsToChars) {
    std::mt19937_64 random(17);
    std::vector<double> values = {0.0,          -0.0, 1.0,   1e-9,   123456789.0,
                                  1234567890.0, 0.5,  1e100, 1e-100, std::numeric_limits<double>::infinity()};
    for (int i = 0; i < 50000; ++i) {
        const double value = std::bit_cast<double>(random());
        if (!std::isnan(value)) values.push_back(value);
        values.push_back(double(random() % 2000000) / 1000.0 - 1000.0);
    }
    for (double value : values) {
        for (int precision : {1, 6, 9, 17}) {
            EXPECT_EQ(portable::generalText(value, precision), standardGeneral(value, precision)) << value;
        }
    }
}

// The build's own choice (standard or portable) gives the standard's text too.
TEST(DecimalText, TheBuildsChoiceAgrees) {
    EXPECT_EQ(shortestText(0.1), "0.1");
    EXPECT_EQ(shortestText(0.1f), "0.1");
    EXPECT_EQ(generalText(1.0 / 3.0, 9), "0.333333333");
    double value = 0;
    const std::string text = "2.5e3";
    EXPECT_EQ(readDecimal(text.data(), text.data() + text.size(), value).ptr, text.data() + text.size());
    EXPECT_EQ(value, 2500.0);
}

}  // namespace
}  // namespace f2
