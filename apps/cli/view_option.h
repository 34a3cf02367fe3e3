#pragma once
/// `--view MODE` of f2 render: what the pixels show (core/render/view_mode.h).
#include <CLI/CLI.hpp>

#include "core/render/view_mode.h"

namespace f2::cli {

/// Adds --view to `command`, storing the mode named into `view`; an unknown
/// name is a usage error that lists the modes.
void addViewOption(CLI::App& command, ViewMode& view);

}  // namespace f2::cli
