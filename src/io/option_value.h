#pragma once
/// The values of command-line options, read by one set of rules for both
/// front ends: f2's CLI11 validators (apps/cli/options.h) and f2-viewer's
/// options (apps/viewer/viewer_options.cpp). A number is the whole text as one
/// decimal number (a leading '+' allowed; no `0x10`, no spaces, nothing after
/// it), finite (no `nan`, `inf`) and in range. Each function returns the value
/// or why it is refused: one phrase without the option's name, which the front
/// end puts before it ("--frame: a frame time must be a finite number, got 'nan'").
#include <string>
#include <string_view>

namespace f2::io {

/// A value read from an option's text, or why it was refused.
template <typename T>
struct OptionValue {
    T value{};
    std::string error;  ///< empty: `value` is the option's value
    bool ok() const { return error.empty(); }
};

/// A whole decimal number in [lo, hi]: "'abc' is not a whole number (expected
/// 1..16)", "0 is outside 1..16".
OptionValue<long> readWholeNumber(std::string_view text, long lo, long hi);

/// A finite decimal number in [lo, hi]; `what` names it in messages ("a frame
/// time must be a finite number, got 'nan'", "'1x' is not a decimal number (a
/// frame time in 0..1e+07)", "-1 is outside 0..1e+07").
OptionValue<double> readFiniteNumber(std::string_view text, double lo, double hi, std::string_view what);

struct ImageSize {
    int width = 0;
    int height = 0;
};

/// "WIDTHxHEIGHT" (1280x720) within the SPEC's image limits (core/scene/limits.h).
OptionValue<ImageSize> readImageSize(std::string_view text);

}  // namespace f2::io
