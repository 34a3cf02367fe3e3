#!/usr/bin/env bash
# Installs what is missing, builds (Release) and runs the main job on the
# embedded default scene: the viewer when there is a display, otherwise
# `f2 render` of frame 0 to f2.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release
cmake --build --preset release
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x build/release/apps/viewer/f2-viewer ]; then
  exec build/release/apps/viewer/f2-viewer "$@"
fi
echo "run: no display (DISPLAY is not set), rendering the default scene with f2 render instead"
build/release/apps/cli/f2 render -o f2.png "$@"
echo "run: wrote $(pwd)/f2.png"
