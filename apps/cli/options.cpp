#include "options.h"

#include <iostream>

#include "io/option_value.h"

namespace f2::cli {

CLI::Validator wholeNumberIn(long lo, long hi) {
    return CLI::Validator([lo, hi](std::string& text) { return io::readWholeNumber(text, lo, hi).error; },
                          "");
}

CLI::Validator finiteNumberIn(double lo, double hi, const std::string& what) {
    return CLI::Validator(
        [lo, hi, what](std::string& text) { return io::readFiniteNumber(text, lo, hi, what).error; }, "");
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
