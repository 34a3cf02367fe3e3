#include "core/parse/number.h"

#include <cmath>
#include <system_error>

#include "core/parse/lexer.h"
#include "core/util/decimal_text.h"

namespace f2 {

ParsedNumber parseNumber(std::string_view token) {
    ParsedNumber result;
    std::string_view digits = token;
    // from_chars does not take a leading '+', but people write "+5".
    if (!digits.empty() && digits.front() == '+') {
        digits.remove_prefix(1);
        if (!digits.empty() && (digits.front() == '+' || digits.front() == '-')) return result;
    }
    if (digits.empty()) return result;

    // Spot "0x.." / "-0x.." for a clearer message; from_chars would stop at 'x'.
    std::string_view unsigned_ = digits.front() == '-' ? digits.substr(1) : digits;
    if (unsigned_.size() > 1 && unsigned_[0] == '0' && (unsigned_[1] == 'x' || unsigned_[1] == 'X')) {
        result.status = NumberStatus::Hexadecimal;
        return result;
    }

    double value = 0;
    const char* end = digits.data() + digits.size();
    const auto [ptr, ec] = readDecimal(digits.data(), end, value);
    if (ec == std::errc::result_out_of_range && ptr == end) {
        result.status = NumberStatus::OutOfRange;
        return result;
    }
    if (ec != std::errc() || ptr != end) return result;  // garbage somewhere
    if (!std::isfinite(value)) {
        result.status = NumberStatus::NotFinite;
        return result;
    }
    if (std::fabs(value) > kMaxNumberMagnitude) {
        result.status = NumberStatus::OutOfRange;
        return result;
    }
    result.value = value == 0 ? 0.0 : value;  // -0 reads as 0
    result.status = NumberStatus::Ok;
    return result;
}

std::string numberErrorMessage(std::string_view token, NumberStatus status) {
    switch (status) {
        case NumberStatus::Ok:
            break;
        case NumberStatus::NotANumber: {
            std::string message = "expected a number, got " + quoteToken(token);
            if (token.find(',') != std::string_view::npos) message += " (the decimal separator is '.')";
            return message;
        }
        case NumberStatus::Hexadecimal:
            return "expected a decimal number, got " + quoteToken(token) + " (hexadecimal is not accepted)";
        case NumberStatus::NotFinite:
            return "expected a finite number, got " + quoteToken(token);
        case NumberStatus::OutOfRange: {
            const bool tiny =
                token.find("e-") != std::string_view::npos || token.find("E-") != std::string_view::npos;
            return "number " + quoteToken(token) + " is out of range" +
                   (tiny ? " (too close to zero; write 0)" : " (the largest magnitude is 3.4e38)");
        }
    }
    return {};
}

}  // namespace f2
