#include "options.h"

#include <charconv>
#include <cmath>
#include <iostream>

namespace f2::cli {

namespace {
/// The whole of `text` as a decimal number of type T (a leading '+' allowed).
template <typename T>
bool parseDecimal(std::string_view text, T& value) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    const char* end = text.data() + text.size();
    auto result = std::from_chars(text.data(), end, value);
    return !text.empty() && result.ec == std::errc{} && result.ptr == end;
}

std::string formatted(double value) {
    std::ostringstream s;
    s << value;
    return s.str();
}
}  // namespace

CLI::Validator wholeNumberIn(long lo, long hi) {
    const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
    return CLI::Validator(
        [lo, hi, range](std::string& text) -> std::string {
            long value = 0;
            if (!parseDecimal(text, value))
                return "'" + text + "' is not a whole number (expected " + range + ")";
            if (value < lo || value > hi) return text + " is outside " + range;
            return {};
        },
        "");
}

CLI::Validator finiteNumberIn(double lo, double hi, const std::string& what) {
    const std::string range = formatted(lo) + ".." + formatted(hi);
    return CLI::Validator(
        [lo, hi, range, what](std::string& text) -> std::string {
            double value = 0;
            if (!parseDecimal(text, value))
                return "'" + text + "' is not a decimal number (" + what + " in " + range + ")";
            if (!std::isfinite(value)) return what + " must be a finite number, got '" + text + "'";
            if (value < lo || value > hi) return text + " is outside " + range;
            return {};
        },
        "");
}

CLI::Validator nonEmptyPath(const std::string& leaveOutTo) {
    return CLI::Validator(
        [leaveOutTo](std::string& text) -> std::string {
            return text.empty() ? "the path is empty (leave it out to " + leaveOutTo + ")" : "";
        },
        "");
}

int usageError(const std::string& command, const std::string& message) {
    const std::string name = command.empty() ? "f2" : "f2 " + command;
    std::cerr << name << ": " << message << " (see " << name << " --help)\n";
    return kUsageError;
}

}  // namespace f2::cli
