#!/usr/bin/env bash
# build_modules.sh WORK: builds both WebAssembly modules (scripts/web.sh
# module) into WORK/simd and WORK/scalar for the web tests (a CTest fixture);
# ccache makes a rebuild quick. Skipped (tests/skip.sh) without emcc.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
. "$here/../skip.sh"
. "$here/needs.sh"
work=$1
needs emcc
mkdir -p "$work"
for variant in simd scalar; do
  start=$(date +%s)
  "$root/scripts/web.sh" module "$variant" "$work/$variant" > "$work/$variant.log" 2>&1 ||
    { tail -30 "$work/$variant.log"; echo "FAIL: the $variant module did not build"; exit 1; }
  echo "the $variant module built in $(( $(date +%s) - start )) s"
done
