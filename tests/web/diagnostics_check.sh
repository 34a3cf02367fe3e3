#!/usr/bin/env bash
# diagnostics_check.sh F2 MODULE_DIR DRIVES.f2: the wasm SIMD module's
# diagnostics are `f2 check`'s on scenes with errors, warnings and a /drive
# without a finite value (web/test/diagnostics_match.js). Skipped
# (tests/skip.sh) without emcc or node.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$here/../skip.sh"
. "$here/needs.sh"
f2=$1 modules=$2 drives=$3
needs emcc node
module=$modules/simd/f2-simd.js
[ -f "$module" ] || { echo "FAIL: no $module: the web.modules test builds it"; exit 1; }
node --no-experimental-fetch "$root/web/test/diagnostics_match.js" "$module" "$f2" "$drives" ||
  { echo "FAIL: the module's diagnostics differ from f2 check's"; exit 1; }
echo "PASS"
