#!/usr/bin/env bash
# view_check.sh F2 IMAGE_COMPARE OUTDIR: `f2 render --view MODE` for every
# mode. --view shaded is the image without --view, byte for byte; every other
# mode gives a different picture of the same size; the modes also reach
# sequences (one file per frame) and are the same on one thread and on two.
set -eu
f2=$1 compare=$2 out=$3
rm -rf "$out" && mkdir -p "$out"
"$f2" render --frame 118 --size 160x120 -o "$out/plain.png" 2>/dev/null
"$f2" render --frame 118 --size 160x120 --view shaded -o "$out/shaded.png" 2>/dev/null
"$compare" same "$out/plain.png" "$out/shaded.png"
for mode in normals depth shadow-mask primitive-ids cost; do
  "$f2" render --frame 118 --size 160x120 --view $mode --threads 1 -o "$out/$mode.png" 2>/dev/null
  "$f2" render --frame 118 --size 160x120 --view $mode --threads 2 -o "$out/$mode-2.png" 2>/dev/null
  "$compare" same "$out/$mode.png" "$out/$mode-2.png"
  if "$compare" same "$out/plain.png" "$out/$mode.png" >/dev/null; then
    echo "FAIL: --view $mode drew the shaded image"; exit 1
  fi
  "$compare" colours "$out/$mode.png" 3
done
"$f2" render --frames 0-2 --size 160x120 --view cost -o "$out/seq/c_%d.png" 2>/dev/null
for i in 0 1 2; do [ -s "$out/seq/c_$i.png" ] || { echo "FAIL: c_$i.png missing"; exit 1; }; done
echo ok
