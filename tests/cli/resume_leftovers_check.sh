#!/usr/bin/env bash
# resume_leftovers_check.sh F2 SCENE DIR: temporary files that a `kill -9`
# left beside a sequence (`f_0001.png.tmp-XXXXXX`) are removed by --resume,
# but only those of the frames this worker renders: another shard's worker
# may be writing its own in the same directory at that moment.
set -eu
f2=$1 scene=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
"$f2" render "$scene" --frames 0-3 --size 16x12 -o "$dir/f_%04d.png" 2>/dev/null
rm "$dir/f_0002.png"
# Leftovers of frames 1 (shard 1 of 2), 2 (missing) and 3 (shard 1), 0 (on disk, shard 0).
for name in f_0000.png.tmp-aB3xY9 f_0001.png.tmp-Qw12Er f_0002.png.tmp-zz99ZZ f_0003.png.tmp-Kk77Lm; do
  head -c 100 /dev/urandom >"$dir/$name"
done
"$f2" render "$scene" --frames 0-3 --size 16x12 --shard 0/2 --resume -o "$dir/f_%04d.png" 2>&1 |
  grep "1 rendered, 1 already on disk"
left=$(ls -a "$dir" | grep '\.tmp-' | tr '\n' ' ')
[ "$left" = "f_0001.png.tmp-Qw12Er f_0003.png.tmp-Kk77Lm " ] ||
  { echo "FAIL: temporaries left: '$left' (expected only shard 1's)"; exit 1; }
[ -s "$dir/f_0002.png" ] || { echo "FAIL: frame 2 not rendered"; exit 1; }
echo "ok: shard 0's leftovers removed, shard 1's kept"
