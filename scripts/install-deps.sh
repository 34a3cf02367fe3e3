#!/usr/bin/env bash
# Installs the Debian 12 packages F2 Stage needs, and nothing that is already
# there. Uses sudo when not root.
#
#   scripts/install-deps.sh          everything: build, tests, benchmarks, video,
#                                    POV-Ray, plots, fuzzing (test.sh, CI)
#   scripts/install-deps.sh --run    only what building f2 and f2-viewer needs (run.sh)
#   scripts/install-deps.sh --web    only what building the browser page needs (web.sh --install)
#   scripts/install-deps.sh --check  installs nothing; exit 0 if everything is there
set -euo pipefail

# Building and running f2 and the viewer.
RUN_PACKAGES=(
  g++ cmake ninja-build pkg-config
  libpng-dev libcli11-dev qt6-base-dev libgl-dev libegl-dev nlohmann-json3-dev libstb-dev
)
# Everything else: tests, benchmarks, video and POV-Ray output, plots, fuzzing.
MORE_PACKAGES=(
  git
  # tests and benchmarks (GNU parallel: the render-farm test)
  libgtest-dev libbenchmark-dev locales xvfb xauth imagemagick x11-apps parallel
  # the Embree peer renderer f2 is compared with (bench/embree_peer)
  libembree-dev libtbb-dev
  # the language server's end-to-end test with a real client
  neovim
  # video and POV-Ray output, plots for `f2 bench --study`
  ffmpeg povray gnuplot-nox
  # Blender opens the glTF export (its importer needs numpy, which Debian's
  # blender package does not pull in)
  blender python3-numpy
  # fuzzing (clang's libFuzzer runtime)
  clang libclang-rt-14-dev
  # the formatting check of .ci/run (scripts/check-format.sh)
  clang-format
  # one build's objects serve the next preset's (CMakeLists.txt: F2_CCACHE)
  ccache
  # the browser playground and its tests (web/, docs/web.md)
  emscripten chromium
)

# The browser page (scripts/web.sh): the core compiled by emscripten, the
# header-only libraries it reads from the host, python3's static server.
WEB_PACKAGES=(cmake ninja-build nlohmann-json3-dev libstb-dev emscripten python3)

mode=${1:-all}
case "$mode" in
  --run) PACKAGES=("${RUN_PACKAGES[@]}") ;;
  --web) PACKAGES=("${WEB_PACKAGES[@]}") ;;
  all | --check) PACKAGES=("${RUN_PACKAGES[@]}" "${MORE_PACKAGES[@]}") ;;
  *) echo "usage: $0 [--run | --web | --check]" >&2; exit 2 ;;
esac

# Node.js and npm for the VS Code extension, its grammar test and the web
# page's bundle (not for run.sh); a Node.js installed another way (with its
# own npm) is kept.
if [ "$mode" != --run ] && ! command -v npm >/dev/null 2>&1; then
  PACKAGES+=(nodejs npm)
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ "$mode" = --check ]; then
  [ ${#missing[@]} -eq 0 ] || { echo "install-deps: missing ${missing[*]}"; exit 1; }
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# A comma-decimal locale, so the tests can prove the parser ignores the system locale.
if [ "$mode" = all ] && ! locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$'; then
  $SUDO localedef -i de_DE -f UTF-8 de_DE.UTF-8 || echo "install-deps: could not generate de_DE.UTF-8"
fi
