#!/usr/bin/env bash
# check.sh F2 IMAGE_COMPARE OUTDIR [--update]: renders every case of
# cases.txt into OUTDIR and compares it pixel for pixel with NAME.png here.
# With --update, writes the renders here instead (then look at them).
set -euo pipefail
f2=$1 compare=$2 out=$3 update=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
cd "$here/../.."
mkdir -p "$out"
failed=0 checked=0
while read -r name args; do
  [[ -z "$name" || "$name" == \#* ]] && continue
  # shellcheck disable=SC2086  # the arguments are words
  "$f2" render $args --threads 2 -o "$out/$name.png" 2>/dev/null
  if [[ "$update" == --update ]]; then
    cp "$out/$name.png" "$here/$name.png"
    echo "updated tests/golden/$name.png"
    continue
  fi
  if [[ ! -f "$here/$name.png" ]]; then
    echo "FAIL: tests/golden/$name.png is missing (check.sh ... --update writes it)"
    failed=$((failed + 1))
  elif ! "$compare" same "$here/$name.png" "$out/$name.png"; then
    echo "FAIL: $name differs from tests/golden/$name.png (render: $out/$name.png)"
    failed=$((failed + 1))
  fi
  checked=$((checked + 1))
done < "$here/cases.txt"
[[ "$update" == --update ]] && exit 0
(( failed == 0 )) || exit 1
(( checked > 0 )) || { echo "FAIL: no cases"; exit 1; }
echo "ok: $checked golden images identical"
