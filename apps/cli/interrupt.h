#pragma once
/// Ctrl+C and `kill`: SIGINT and SIGTERM raise a flag that long renders poll,
/// so they stop between (or inside) frames and clean up their files instead
/// of dying with a half-written one.
#include <atomic>

namespace f2::cli {

/// Installs the handlers (idempotent).
void installInterruptHandlers();
/// Raised by the first SIGINT/SIGTERM; handed to Renderer::render as `cancel`.
const std::atomic<bool>& interruptFlag();
/// The signal that raised the flag (0 if none); the exit code is 128 + it.
int interruptSignal();

}  // namespace f2::cli
