#!/usr/bin/env bash
# page_check.sh F2 MODULE_DIR WORK: the playground page (both modules from
# build_modules.sh) served by python3 -m http.server and opened in Debian's
# chromium by puppeteer-core (web/test/page_check.js), with wasm SIMD and with
# ?nosimd (web/test/page_check.js says what it checks): the pictures are
# `f2 render`'s (frame 0, --aa 3, frame 120) byte for byte, the editor's
# diagnostics `f2 check`'s and its squiggles, completion and hover `f2 lsp`'s.
# Skipped (tests/skip.sh) without emcc, node, chromium or the npm packages of
# web and web/test.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$here/../skip.sh"
. "$here/needs.sh"
f2=$1 modules=$2 work=$3
needs emcc node chromium puppeteer esbuild
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work"
"$root/scripts/web.sh" dist "$modules/simd" "$modules/scalar" "$work/dist" || fail "the page could not be assembled"
for frame in 0 120; do
  "$f2" render --frame $frame --size 640x480 -o "$work/frame$frame.png" > /dev/null 2>&1 || fail "f2 render --frame $frame"
done
# The page's paused picture: 3 x 3 samples (its default ?aa).
"$f2" render --frame 0 --size 640x480 --aa 3 -o "$work/frame0_aa.png" > /dev/null 2>&1 || fail "f2 render --aa 3"
# The page shows LINE:COL: error: message, f2 check FILE:LINE:COL: error: message.
error_line="/sphere s1 1 2"
expected=$({ cat "$root/scenes/demo.f2"; echo "$error_line"; } | "$f2" check - 2>&1 | head -1)
expected=${expected#<stdin>:}
[ -n "$expected" ] || fail "f2 check found no error in the demo with '$error_line'"

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
for query in "" "?nosimd"; do
  node "$root/web/test/page_check.js" "http://127.0.0.1:$port/$query" "$f2" "$work" \
    "$error_line" "$expected" "$work/page${query#?}.png" || status=1
done
[ $status -eq 0 ] || fail "the page's picture or console"
echo "PASS"
