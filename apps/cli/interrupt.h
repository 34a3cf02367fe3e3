#pragma once
/// Ctrl+C, `kill` and a closed terminal: SIGINT, SIGTERM and SIGHUP (unless
/// ignored, as under nohup) raise a flag that long renders poll,
/// so they stop between (or inside) frames and clean up their files instead
/// of dying with a half-written one.
#include <atomic>

namespace f2::cli {

/// Installs the handlers (idempotent).
void installInterruptHandlers();
/// Raised by the first SIGINT/SIGTERM/SIGHUP; handed to Renderer::render as `cancel`.
const std::atomic<bool>& interruptFlag();
/// The first signal that raised the flag (0 if none); the exit code is 128 + it.
int interruptSignal();

}  // namespace f2::cli
