#!/usr/bin/env bash
# Installs every Debian 12 package F2 Stage needs to build, test and run, and
# nothing when they are already there. Uses sudo when not root.
set -euo pipefail

PACKAGES=(
  # toolchain and build
  g++ cmake ninja-build pkg-config git
  # libraries
  libpng-dev libcli11-dev qt6-base-dev libgl-dev libegl-dev nlohmann-json3-dev
  # tests and benchmarks (GNU parallel: the render-farm test)
  libgtest-dev libbenchmark-dev locales xvfb xauth imagemagick x11-apps parallel
  # the Embree peer renderer f2 is compared with (bench/embree_peer)
  libembree-dev libtbb-dev
  # the language server's end-to-end test with a real client
  neovim
  # video and POV-Ray output, plots for `f2 bench --study`
  ffmpeg povray gnuplot-nox
  # fuzzing (clang's libFuzzer runtime)
  clang libclang-rt-14-dev
)

# Node.js and npm for the VS Code extension and its grammar test; a Node.js
# installed another way (with its own npm) is kept.
if ! command -v npm >/dev/null 2>&1; then
  PACKAGES+=(nodejs npm)
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "install-deps: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# A comma-decimal locale, so the tests can prove the parser ignores the system locale.
if ! locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$'; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO localedef -i de_DE -f UTF-8 de_DE.UTF-8 || echo "install-deps: could not generate de_DE.UTF-8"
fi
