#pragma once
/// Checks of option values shared by the subcommands, stricter than CLI11's
/// own conversions: decimal numbers only (no `0x10`), finite (no `nan`,
/// `inf`), and messages that say what was expected rather than "not in range"
/// for a word that is not a number at all. The rules themselves are
/// io/option_value.h, which f2-viewer's options use too.
#include <CLI/CLI.hpp>
#include <string>

namespace f2::cli {

/// Exit code of every usage error (bad option, value or combination).
inline constexpr int kUsageError = 2;

/// A whole decimal number in [lo, hi]: "'abc' is not a whole number".
CLI::Validator wholeNumberIn(long lo, long hi);

/// A finite decimal number in [lo, hi]; `what` names it in messages
/// ("a frame time must be a finite number, got 'nan'").
CLI::Validator finiteNumberIn(double lo, double hi, const std::string& what);

/// A path that is not the empty string (`f2 render ''` is a mistake, not the
/// default scene); `leaveOutTo` says what leaving the argument out does.
CLI::Validator nonEmptyPath(const std::string& leaveOutTo);

/// Prints "f2 COMMAND: message (see f2 COMMAND --help)" on stderr and returns
/// kUsageError; `command` is the subcommand's name, or "" for f2 itself.
int usageError(const std::string& command, const std::string& message);

}  // namespace f2::cli
