#!/usr/bin/env bash
# The browser playground (docs/web.md): builds the WebAssembly module twice
# (wasm SIMD and the fallback without it) with Debian's emscripten, puts the
# page into web/dist/ and serves it.
#
# Usage:
#   scripts/web.sh [--install] [serve [PORT]]   build web/dist/; serve: then on http://localhost:PORT (8000)
#   scripts/web.sh module simd|scalar DIR        one module into DIR (DIR/f2-simd.js or DIR/f2.js + .wasm)
#   scripts/web.sh dist SIMD_DIR SCALAR_DIR OUT  the page from two built modules into OUT
# --install: first the Debian packages the page needs when missing
# (scripts/install-deps.sh --web: emscripten, cmake, ...; sudo when not root),
# and the npm packages (web/package.json: CodeMirror, esbuild) when missing.
# -j: F2_WEB_JOBS (default 2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=${F2_WEB_JOBS:-2}

# Debian's emcc runs acorn under node, found in Debian's node folder; another
# node first on the PATH does not look there.
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$root}

if [ "${1:-}" = --install ]; then
  shift
  "$root/scripts/install-deps.sh" --web
  [ -x "$root/web/node_modules/.bin/esbuild" ] || "$root/scripts/install-node-packages.sh"
fi
command -v emcc > /dev/null || { echo "web.sh: emcc not found: apt-get install emscripten (or scripts/web.sh --install)" >&2; exit 1; }

# module simd|scalar DIR: configure (once) and build one variant.
build_module() {
  local variant=$1 dir=$2 simd=ON
  [ "$variant" = scalar ] && simd=OFF
  mkdir -p "$(dirname "$dir")"  # build/ of a fresh clone
  if [ ! -f "$dir/build.ninja" ]; then
    emcmake cmake -S "$root/web" -B "$dir" -G Ninja -DF2_WASM_SIMD=$simd > "$dir.configure.log" 2>&1 ||
      { cat "$dir.configure.log" >&2; exit 1; }
  fi
  cmake --build "$dir" -j "$jobs"
}

# dist SIMD_DIR SCALAR_DIR OUT: the page's files and both modules into OUT.
assemble() {
  local out=$3
  rm -rf "$out" && mkdir -p "$out"
  cp "$1/f2-simd.js" "$1/f2-simd.wasm" "$2/f2.js" "$2/f2.wasm" \
     "$root"/web/src/*.html "$root"/web/src/*.js "$root"/web/src/*.css "$root/scenes/demo.f2" "$out/"
  # The editor: CodeMirror 6 and web/editor/ in one script (esbuild, web/package.json).
  [ -x "$root/web/node_modules/.bin/esbuild" ] ||
    { echo "web.sh: no esbuild in web/node_modules: run scripts/install-node-packages.sh (or web.sh --install)" >&2; exit 1; }
  "$root/web/node_modules/.bin/esbuild" "$root/web/editor/f2_editor.js" --bundle --minify --format=iife \
    --target=es2020 --log-level=warning --outfile="$out/editor.js"
  # The Examples menu: the gallery's scenes and their list.
  mkdir -p "$out/examples"
  cp "$root"/scenes/gallery/*.f2 "$out/examples/"
  (cd "$out/examples" && printf '%s\n' *.f2 > index.txt)
}

if [ "${1:-}" = dist ]; then
  [ $# -eq 4 ] || { echo "usage: scripts/web.sh dist SIMD_DIR SCALAR_DIR OUT" >&2; exit 2; }
  assemble "$2" "$3" "$4"
  exit 0
fi

if [ "${1:-}" = module ]; then
  [ $# -eq 3 ] && { [ "$2" = simd ] || [ "$2" = scalar ]; } || { echo "usage: scripts/web.sh module simd|scalar DIR" >&2; exit 2; }
  mkdir -p "$(dirname "$3")"
  build_module "$2" "$3"
  exit 0
fi

build_module simd "$root/build/web-simd"
build_module scalar "$root/build/web-scalar"
dist=$root/web/dist
assemble "$root/build/web-simd" "$root/build/web-scalar" "$dist"
echo "web.sh: the page is in web/dist/"

if [ "${1:-}" = serve ]; then
  port=${2:-8000}
  echo "web.sh: serving on http://localhost:$port (Ctrl-C stops)"
  exec python3 -m http.server "$port" --bind 127.0.0.1 --directory "$dist"
fi
