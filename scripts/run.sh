#!/usr/bin/env bash
# Installs what the main job needs (only that: tests, video and plots are
# test.sh's), builds (Release) and runs it on the embedded default scene: the
# viewer when there is a display, otherwise `f2 render` of frame 0 to f2.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --run
# Without the test and benchmark libraries, build f2 and the viewer only;
# with them (a developer's machine) keep the full build that test.sh makes.
if scripts/install-deps.sh --check >/dev/null; then
  cmake --preset release
else
  cmake --preset release -DF2_BUILD_TESTS=OFF -DF2_BUILD_BENCH=OFF
fi
cmake --build --preset release
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x build/release/apps/viewer/f2-viewer ]; then
  exec build/release/apps/viewer/f2-viewer "$@"
fi
echo "run: no display (DISPLAY is not set), rendering the default scene with f2 render instead"
build/release/apps/cli/f2 render -o f2.png "$@"
echo "run: wrote $(pwd)/f2.png"
