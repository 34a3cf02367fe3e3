#pragma once
/// Decimal text of floating-point numbers, in the C locale whatever the
/// process locale is. The standard's std::from_chars / std::to_chars where the
/// library has them for floating point (libstdc++); where it has not (libc++
/// 14, the WebAssembly build) a portable version on C's strtod and snprintf,
/// tested equal to the standard's on every native build (decimal_text_test).
#include <charconv>
#include <string>
#include <system_error>

#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
#define F2_FLOAT_CHARCONV 1
#else
#define F2_FLOAT_CHARCONV 0
#endif

namespace f2 {

struct DecimalRead {
    const char* ptr;
    std::errc ec;
};

/// The portable versions, compiled on every build so that tests compare them
/// with the standard library's.
namespace portable {
/// As std::from_chars(first, last, value, std::chars_format::general).
DecimalRead readDecimal(const char* first, const char* last, double& value);
/// As std::to_chars(value): the shortest text that reads back as `value`.
std::string shortestText(double value);
std::string shortestText(float value);
/// As std::to_chars(value, std::chars_format::general, precision) (printf's %g).
std::string generalText(double value, int precision);
}  // namespace portable

#if F2_FLOAT_CHARCONV
inline DecimalRead readDecimal(const char* first, const char* last, double& value) {
    const auto [ptr, ec] = std::from_chars(first, last, value, std::chars_format::general);
    return {ptr, ec};
}
template <class Number>
std::string shortestText(Number value) {
    char buffer[32];
    return {buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr};
}
inline std::string generalText(double value, int precision) {
    char buffer[64];
    return {buffer,
            std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, precision).ptr};
}
#else
using portable::generalText;
using portable::readDecimal;
using portable::shortestText;
#endif

}  // namespace f2
