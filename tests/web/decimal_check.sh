#!/usr/bin/env bash
# decimal_check.sh NATIVE_PROBE MODULE_DIR WORK: web/test/decimal_probe.cpp
# built natively (the standard library's from_chars/to_chars) and in both
# WebAssembly builds (the portable versions on musl) must print the same
# lines: ~100,000 numbers read and written. Skipped (tests/skip.sh) without
# emcc or node.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../skip.sh"
. "$here/needs.sh"
native=$1 modules=$2 work=$3
needs emcc node
fail() { echo "FAIL: $*"; exit 1; }
mkdir -p "$work"
"$native" > "$work/native.txt" || fail "the native probe failed"
for variant in simd scalar; do
  probe=$modules/$variant/f2_decimal_probe.js
  [ -f "$probe" ] || fail "no $probe: the web.modules test builds it"
  node --no-experimental-fetch "$probe" > "$work/$variant.txt" || fail "the $variant probe failed"
  if ! cmp -s "$work/native.txt" "$work/$variant.txt"; then
    diff "$work/native.txt" "$work/$variant.txt" | head -20
    fail "the $variant build reads or writes numbers differently"
  fi
  echo "$variant: $(wc -l < "$work/$variant.txt") lines, the same as the native build's"
done
echo "PASS"
