#!/usr/bin/env bash
# resume_check.sh DIR F2 ARGS...: renders `F2 ARGS...` (a sequence) straight
# through, then again as a farm task that was killed: every other frame is
# already on disk and --resume renders the rest, so its renderer plays another
# history. Every frame must equal the straight render byte for byte.
set -eu
dir=$1
shift
rm -rf "$dir" && mkdir -p "$dir/resumed"
"$@" -o "$dir/straight/f_%04d.png" 2>/dev/null
kept=0
for f in $(ls "$dir/straight"); do
  frame=$((10#$(sed 's/f_\([0-9]*\)\.png/\1/' <<<"$f")))
  if [ $((frame % 2)) -eq 0 ]; then cp "$dir/straight/$f" "$dir/resumed/$f"; kept=$((kept + 1)); fi
done
"$@" --resume -o "$dir/resumed/f_%04d.png" 2>/dev/null
total=0
for f in $(ls "$dir/straight"); do
  cmp "$dir/straight/$f" "$dir/resumed/$f" || { echo "FAIL: $f differs after --resume"; exit 1; }
  total=$((total + 1))
done
[ "$kept" -gt 0 ] && [ "$total" -gt "$kept" ] || { echo "FAIL: nothing was resumed ($kept of $total kept)"; exit 1; }
echo "ok: $((total - kept)) frames rendered by --resume equal the straight render"
