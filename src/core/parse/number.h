#pragma once
/// Decimal numbers of the scene language (SPEC 7), read the same way whatever
/// the process locale is.
#include <string>
#include <string_view>

namespace f2 {

enum class NumberStatus {
    Ok,
    NotANumber,   ///< empty, letters, trailing garbage ("1.5x"), "1,5", "+-1"
    Hexadecimal,  ///< "0x10": only decimal numbers are accepted
    NotFinite,    ///< "nan", "inf", "infinity"
    OutOfRange,   ///< beyond single precision (1e39, 1e400) or too small for a double (1e-400)
};

struct ParsedNumber {
    double value = 0;
    NumberStatus status = NumberStatus::NotANumber;
};

/// Largest magnitude accepted: scene values end up in `float`, so anything
/// beyond FLT_MAX would silently become infinity.
inline constexpr double kMaxNumberMagnitude = 3.4028234663852886e38;

/// Parses a whole token as a finite decimal number (optional sign, digits,
/// optional fraction and exponent). Reads with readDecimal (decimal_text.h), so
/// the C locale's '.' is the decimal point regardless of setlocale().
ParsedNumber parseNumber(std::string_view token);

/// The message for a token that is not a number (status is not Ok), such as
/// "expected a number, got 'abc'".
std::string numberErrorMessage(std::string_view token, NumberStatus status);

}  // namespace f2
