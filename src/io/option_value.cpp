#include "option_value.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <system_error>

#include "core/scene/limits.h"

namespace f2::io {

namespace {
/// The whole of `text` as a decimal number of type T (a leading '+' allowed).
template <typename T>
std::errc parseDecimal(std::string_view text, T& value) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    if (text.empty()) return std::errc::invalid_argument;
    const char* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value);
    if (result.ec == std::errc{} && result.ptr != end) return std::errc::invalid_argument;
    // Out of range of T with nothing after it: a number, but no T holds it.
    return result.ec == std::errc::result_out_of_range && result.ptr != end ? std::errc::invalid_argument
                                                                            : result.ec;
}

std::string formatted(double value) {
    std::ostringstream s;
    s << value;
    return s.str();
}

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }
}  // namespace

OptionValue<long> readWholeNumber(std::string_view text, long lo, long hi) {
    const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
    OptionValue<long> out;
    const std::errc ec = parseDecimal(text, out.value);
    if (ec == std::errc::result_out_of_range)
        out.error = std::string(text) + " is outside " + range;
    else if (ec != std::errc{})
        out.error = quoted(text) + " is not a whole number (expected " + range + ")";
    else if (out.value < lo || out.value > hi)
        out.error = std::string(text) + " is outside " + range;
    return out;
}

OptionValue<double> readFiniteNumber(std::string_view text, double lo, double hi, std::string_view what) {
    const std::string range = formatted(lo) + ".." + formatted(hi);
    OptionValue<double> out;
    const std::errc ec = parseDecimal(text, out.value);
    if (ec == std::errc::result_out_of_range)  // 1e400 (or 1e-400: too small for a double)
        out.error =
            quoted(text) + " is out of the range of numbers (" + std::string(what) + " in " + range + ")";
    else if (ec != std::errc{})
        out.error = quoted(text) + " is not a decimal number (" + std::string(what) + " in " + range + ")";
    else if (!std::isfinite(out.value))
        out.error = std::string(what) + " must be a finite number, got " + quoted(text);
    else if (out.value < lo || out.value > hi)
        out.error = std::string(text) + " is outside " + range;
    return out;
}

OptionValue<ImageSize> readImageSize(std::string_view text) {
    OptionValue<ImageSize> out;
    const auto x = text.find('x');
    const char* begin = text.data();
    const char* end = begin + text.size();
    int w = 0, h = 0;
    if (x == std::string_view::npos || x == 0 || x + 1 == text.size() ||
        std::from_chars(begin, begin + x, w).ptr != begin + x ||
        std::from_chars(begin + x + 1, end, h).ptr != end) {
        out.error = "expected WIDTHxHEIGHT such as 800x600, got " + quoted(text);
    } else if (!imageSizeAllowed(w, h)) {
        out.error = std::string(text) + " is outside 1.." + std::to_string(kMaxImageSide) + " a side and " +
                    std::to_string(kMaxImagePixels) + " pixels in all";
    } else {
        out.value = ImageSize{w, h};
    }
    return out;
}

}  // namespace f2::io
