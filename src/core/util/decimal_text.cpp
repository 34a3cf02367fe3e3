#include "core/util/decimal_text.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

// The portable versions hand C's strtod and snprintf only text without a
// decimal point (digits and an exponent) and read back only digits, so the
// locale's decimal separator never matters; both functions round correctly
// in glibc and in musl (emscripten).

namespace f2::portable {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
char lower(char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; }

/// Whether [p, last) starts with `word` (lower case), ignoring case.
bool startsWith(const char* p, const char* last, const char* word) {
    for (; *word; ++word, ++p) {
        if (p == last || lower(*p) != *word) return false;
    }
    return true;
}

/// Reads the decimal number digits × 10^exponent (digits without a point).
template <class Number>
Number readScaled(const std::string& digits, std::int64_t exponent) {
    const std::string text = digits + "e" + std::to_string(exponent);
    if constexpr (sizeof(Number) == sizeof(float)) {
        return std::strtof(text.c_str(), nullptr);
    } else {
        return std::strtod(text.c_str(), nullptr);
    }
}

/// The digits and decimal exponent of a finite positive value written with
/// `count` significant digits: value ≈ d.ddd × 10^exponent.
struct Digits {
    std::string digits;
    int exponent = 0;
};

Digits roundedDigits(double value, int count) {
    char buffer[64];
    const int n = std::snprintf(buffer, sizeof buffer, "%.*e", count - 1, value);
    Digits out;
    int i = 0;
    for (; i < n && lower(buffer[i]) != 'e'; ++i) {
        if (isDigit(buffer[i])) out.digits += buffer[i];
    }
    out.exponent = std::atoi(buffer + i + 1);
    return out;
}

/// `digits` plus `step` (±1) in the last place, if that keeps the digit count.
bool stepDigits(std::string& digits, int step) {
    std::uint64_t n = std::strtoull(digits.c_str(), nullptr, 10);
    if (step < 0 && n == 0) return false;
    n = step > 0 ? n + 1 : n - 1;
    std::string text = std::to_string(n);
    if (text.size() != digits.size()) return false;
    digits = text;
    return true;
}

/// The shortest digits that read back as `value` (finite, > 0); among those
/// the nearest, as std::to_chars chooses.
template <class Number>
Digits shortestDigits(Number value) {
    const int most = std::numeric_limits<Number>::max_digits10;
    for (int count = 1; count < most; ++count) {
        Digits d = roundedDigits(double(value), count);
        const auto readsBack = [&](const std::string& digits) {
            return readScaled<Number>(digits, std::int64_t(d.exponent) - (count - 1)) == value;
        };
        if (readsBack(d.digits)) return d;
        // Just above a power of two the values below lie closer together, so
        // the nearest digits may miss while the next ones up still read back.
        for (int step : {1, -1}) {
            std::string other = d.digits;
            if (stepDigits(other, step) && readsBack(other)) return {other, d.exponent};
        }
    }
    return roundedDigits(double(value), most);
}

/// std::to_chars's plain form: the digits in fixed or scientific notation,
/// whichever is shorter (fixed on a tie).
template <class Number>
std::string shortest(Number value) {
    if (std::isnan(value)) return std::signbit(value) ? "-nan" : "nan";
    const std::string sign = std::signbit(value) ? "-" : "";
    if (std::isinf(value)) return sign + "inf";
    if (value == 0) return sign + "0";
    Digits d = shortestDigits(std::fabs(value));
    while (d.digits.size() > 1 && d.digits.back() == '0') d.digits.pop_back();
    const int n = int(d.digits.size()), x = d.exponent;

    std::string scientific = d.digits.substr(0, 1);
    if (n > 1) scientific += "." + d.digits.substr(1);
    const int magnitude = x < 0 ? -x : x;
    scientific += std::string(x < 0 ? "e-" : "e+") + (magnitude < 10 ? "0" : "") + std::to_string(magnitude);

    std::string fixed;
    if (x >= n - 1) {
        // A whole number: of the texts this long the nearest is its exact value
        // (to_chars writes 2^55 as 36028797018963968, not ...970).
        char buffer[400];
        const int count = std::snprintf(buffer, sizeof buffer, "%.0f", std::fabs(double(value)));
        for (int i = 0; i < count; ++i) {
            if (isDigit(buffer[i])) fixed += buffer[i];
        }
    } else if (x >= 0) {
        fixed = d.digits.substr(0, std::size_t(x + 1)) + "." + d.digits.substr(std::size_t(x + 1));
    } else {
        fixed = "0." + std::string(std::size_t(-x - 1), '0') + d.digits;
    }
    return sign + (fixed.size() <= scientific.size() ? fixed : scientific);
}

}  // namespace

DecimalRead readDecimal(const char* first, const char* last, double& value) {
    const char* p = first;
    const bool negative = p != last && *p == '-';
    if (negative) ++p;
    if (startsWith(p, last, "inf")) {
        p += startsWith(p, last, "infinity") ? 8 : 3;
        value = negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
        return {p, std::errc{}};
    }
    if (startsWith(p, last, "nan")) {
        p += 3;
        if (p != last && *p == '(') {  // nan(n-char-sequence)
            const char* q = p + 1;
            while (q != last && (isDigit(*q) || *q == '_' || (lower(*q) >= 'a' && lower(*q) <= 'z'))) ++q;
            if (q != last && *q == ')') p = q + 1;
        }
        value =
            negative ? -std::numeric_limits<double>::quiet_NaN() : std::numeric_limits<double>::quiet_NaN();
        return {p, std::errc{}};
    }

    std::string digits = negative ? "-" : "";
    std::int64_t exponent = 0;  // 64 bits also where long has 32 (WebAssembly)
    int count = 0;
    for (; p != last && isDigit(*p); ++p, ++count) digits += *p;
    if (p != last && *p == '.') {
        ++p;
        for (; p != last && isDigit(*p); ++p, ++count, --exponent) digits += *p;
    }
    if (count == 0) return {first, std::errc::invalid_argument};
    if (p != last && lower(*p) == 'e') {
        const char* q = p + 1;
        const bool minus = q != last && *q == '-';
        if (q != last && (*q == '-' || *q == '+')) ++q;
        if (q != last && isDigit(*q)) {
            // Saturated: far beyond any double either way, and no overflow.
            std::int64_t written = 0;
            for (; q != last && isDigit(*q); ++q)
                written = std::min<std::int64_t>(written * 10 + (*q - '0'), 1000000000);
            exponent += minus ? -written : written;
            p = q;
        }
    }
    const double read = readScaled<double>(digits, exponent);
    const bool zeroDigits = digits.find_first_of("123456789") == std::string::npos;
    if (std::isinf(read) || (read == 0 && !zeroDigits)) return {p, std::errc::result_out_of_range};
    value = read;
    return {p, std::errc{}};
}

std::string shortestText(double value) { return shortest(value); }
std::string shortestText(float value) { return shortest(value); }

std::string generalText(double value, int precision) {
    if (std::isnan(value) || std::isinf(value)) return shortest(value);
    char buffer[64];
    const int n = std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    // The locale's decimal separator (possibly several bytes) becomes '.'.
    std::string text;
    for (int i = 0; i < n; ++i) {
        const char c = buffer[i];
        if (isDigit(c) || c == '-' || c == '+' || c == 'e') {
            text += c;
        } else if (text.empty() || text.back() != '.') {
            text += '.';
        }
    }
    return text;
}

}  // namespace f2::portable
