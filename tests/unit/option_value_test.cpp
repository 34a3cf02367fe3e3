// The rules both front ends read option values by (src/io/option_value.h).
#include "io/option_value.h"

#include <gtest/gtest.h>

#include <string>

namespace f2::io {
namespace {

TEST(OptionValue, FiniteNumbersInRangeAreRead) {
    for (const auto& [text, value] :
         {std::pair{"0", 0.0}, {"12.5", 12.5}, {"+3", 3.0}, {"1e7", 1e7}, {"-0", 0.0}}) {
        const OptionValue<double> read = readFiniteNumber(text, 0.0, 1e7, "a frame time");
        EXPECT_TRUE(read.ok()) << text << ": " << read.error;
        EXPECT_EQ(read.value, value) << text;
    }
}

TEST(OptionValue, NonFiniteNumbersAreRefused) {
    for (const char* text : {"nan", "NAN", "-nan", "nan(1)", "inf", "+inf", "-inf", "Infinity"}) {
        EXPECT_EQ(readFiniteNumber(text, 0.0, 1e7, "a frame time").error,
                  "a frame time must be a finite number, got '" + std::string(text) + "'");
    }
}

TEST(OptionValue, NumbersOutOfRangeAreRefused) {
    EXPECT_EQ(readFiniteNumber("1e300", 0.0, 1e7, "a frame time").error, "1e300 is outside 0..1e+07");
    EXPECT_EQ(readFiniteNumber("-1", 0.0, 1e7, "a frame time").error, "-1 is outside 0..1e+07");
    EXPECT_EQ(readFiniteNumber("0", 0.001, 86400, "a duration").error, "0 is outside 0.001..86400");
    // More than a double holds: refused, not read as infinity or the largest double.
    EXPECT_EQ(readFiniteNumber("1e400", 0.0, 1e7, "a frame time").error,
              "'1e400' is out of the range of numbers (a frame time in 0..1e+07)");
    EXPECT_EQ(readWholeNumber("99999999999999999999", 0, 1024).error,
              "99999999999999999999 is outside 0..1024");
    EXPECT_EQ(readWholeNumber("0", 1, 16).error, "0 is outside 1..16");
}

TEST(OptionValue, WhatIsNotOneDecimalNumberIsRefused) {
    for (const char* text : {"abc", "1x", "0x10", "", " 1", "1 ", "+", "++1", "1e", "1,5"}) {
        EXPECT_EQ(readFiniteNumber(text, 0.0, 1e7, "a frame time").error,
                  "'" + std::string(text) + "' is not a decimal number (a frame time in 0..1e+07)");
    }
    for (const char* text : {"abc", "1x", "1.5", "1e3", "0x10", ""})
        EXPECT_EQ(readWholeNumber(text, 1, 16).error,
                  "'" + std::string(text) + "' is not a whole number (expected 1..16)");
    EXPECT_EQ(readWholeNumber("+16", 1, 16).value, 16);
}

TEST(OptionValue, ImageSizes) {
    const OptionValue<ImageSize> hd = readImageSize("1280x720");
    ASSERT_TRUE(hd.ok()) << hd.error;
    EXPECT_EQ(hd.value.width, 1280);
    EXPECT_EQ(hd.value.height, 720);
    for (const char* text : {"12by3", "x600", "800x", "1e3x600", "800x600x2", "800 x600", "nanxnan"})
        EXPECT_EQ(readImageSize(text).error,
                  "expected WIDTHxHEIGHT such as 800x600, got '" + std::string(text) + "'");
    EXPECT_EQ(readImageSize("16385x1").error,
              "16385x1 is outside 1..16384 a side and 67108864 pixels in all");
    EXPECT_FALSE(readImageSize("0x600").ok());
    EXPECT_FALSE(readImageSize("16384x16384").ok());  // each side fits, the pixels do not
}

}  // namespace
}  // namespace f2::io
