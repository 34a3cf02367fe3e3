#!/usr/bin/env bash
# page_check.sh F2 MODULE_DIR WORK: the playground page (both modules from
# build_modules.sh) served by python3 -m http.server and opened in Debian's
# chromium by puppeteer-core (web/test/page_check.js), with wasm SIMD and with
# ?nosimd: no console error, and the canvas holds `f2 render --frame 0` of the
# default scene at 640x480 byte for byte. Skipped (tests/skip.sh) without
# emcc, node, chromium or the npm packages of web/test.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$here/../skip.sh"
f2=$1 modules=$2 work=$3
command -v emcc > /dev/null 2>&1 || skip_missing "emcc is not installed (apt-get install emscripten; scripts/web.sh --install)"
command -v node > /dev/null 2>&1 || skip_missing "node is not installed (scripts/install-deps.sh installs nodejs)"
command -v chromium > /dev/null 2>&1 || skip_missing "chromium is not installed (apt-get install chromium)"
[ -d "$root/web/test/node_modules/puppeteer-core" ] ||
  skip_missing "npm package puppeteer-core is missing in web/test: run scripts/install-node-packages.sh"
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
"$root/scripts/web.sh" dist "$modules/simd" "$modules/scalar" "$work/dist" || fail "the page could not be assembled"
"$f2" render --frame 0 --size 640x480 -o "$work/native.png" > /dev/null 2>&1 || fail "f2 render"

# A free port: http.server exits at once when its port is taken.
server=
for attempt in 1 2 3 4 5; do
  port=$(( 20000 + RANDOM % 20000 ))
  python3 -m http.server "$port" --bind 127.0.0.1 --directory "$work/dist" > "$work/server.log" 2>&1 &
  server=$!
  sleep 1
  kill -0 "$server" 2> /dev/null && break
  server=
done
[ -n "$server" ] || fail "python3 -m http.server did not start"
trap 'kill "$server" 2> /dev/null' EXIT

status=0
node "$root/web/test/page_check.js" "http://127.0.0.1:$port/" "$work/native.png" "$work/page.png" || status=1
node "$root/web/test/page_check.js" "http://127.0.0.1:$port/?nosimd" "$work/native.png" || status=1
[ $status -eq 0 ] || fail "the page's picture or console"
echo "PASS"
