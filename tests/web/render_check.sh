#!/usr/bin/env bash
# render_check.sh simd|scalar F2 MODULE_DIR WORK SCENE@FRAME...: for each
# scene and frame, the module (built by build_modules.sh) renders the picture
# at 160x120 in uneven bands of rows, as the page's workers do, and it must
# equal `f2 render`'s byte for byte (web/test/render_matches_native.js).
# Skipped (tests/skip.sh) without emcc or node.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$here/../skip.sh"
. "$here/needs.sh"
variant=$1 f2=$2 modules=$3 work=$4
needs emcc node
shift 4
fail() { echo "FAIL: $*"; exit 1; }
module=$modules/$variant/f2.js
[ "$variant" = simd ] && module=$modules/simd/f2-simd.js
[ -f "$module" ] || fail "no $module: the web.modules test builds it"
mkdir -p "$work"

status=0
for item in "$@"; do
  scene=${item%@*} frame=${item##*@}
  png=$work/$(basename "$scene" .f2)_$frame.png
  "$f2" render "$scene" --frame "$frame" --size 160x120 -o "$png" > /dev/null 2>&1 || fail "f2 render $scene --frame $frame"
  # The 3.1.6 loader would fetch the .wasm with node's fetch, which cannot read files.
  node --no-experimental-fetch "$root/web/test/render_matches_native.js" "$module" "$scene" "$png" "$frame" || status=1
done
[ $status -eq 0 ] || fail "the module's pictures differ from f2 render's"
echo "PASS"
