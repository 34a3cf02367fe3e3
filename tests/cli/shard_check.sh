#!/usr/bin/env bash
# shard_check.sh [--parallel JOBS] N DIR F2 ARGS...: renders `F2 ARGS...` as
# one sequence and as N shards run side by side (like N farm workers, each in
# its own directory); every shard K holds exactly the frames = K (mod N), and
# together they are the unsharded sequence: the same names, each once,
# byte-identical. The shards start as background jobs of this shell, or with
# --parallel through GNU parallel with JOBS at a time, as docs/output.md shows.
set -eu
jobs=0
if [ "$1" = --parallel ]; then jobs=$2; shift 2; fi
n=$1 dir=$2
shift 2
rm -rf "$dir" && mkdir -p "$dir"
"$@" -o "$dir/all/f_%04d.png" 2>/dev/null
if [ "$jobs" -gt 0 ]; then
  # --quote: each argument stays one argument; a failed shard fails parallel.
  parallel --will-cite --quote --halt now,fail=1 -j "$jobs" "$@" --shard "{}/$n" -o "$dir/shard{}/f_%04d.png" \
    ::: $(seq 0 $((n - 1))) 2>/dev/null
else
  pids=()
  for ((k = 0; k < n; ++k)); do "$@" --shard "$k/$n" -o "$dir/shard$k/f_%04d.png" 2>/dev/null & pids+=($!); done
  for pid in "${pids[@]}"; do wait "$pid"; done
fi
total=0
for ((k = 0; k < n; ++k)); do
  [ -d "$dir/shard$k" ] || mkdir "$dir/shard$k"  # a shard with no frames writes nothing
  for f in $(ls "$dir/shard$k"); do
    frame=$((10#$(sed 's/f_\([0-9]*\)\.png/\1/' <<<"$f")))
    [ $((frame % n)) -eq "$k" ] || { echo "FAIL: shard $k rendered frame $frame"; exit 1; }
    cmp "$dir/shard$k/$f" "$dir/all/$f" || { echo "FAIL: $f differs from the unsharded render"; exit 1; }
    total=$((total + 1))
  done
done
all=$(ls "$dir/all" | wc -l)
union=$(ls "$dir"/shard* | grep -c '\.png$' || true)
[ "$total" -eq "$all" ] && [ "$union" -eq "$all" ] || { echo "FAIL: shards hold $total frames, unsharded $all"; exit 1; }
echo "ok: $n shards$([ "$jobs" -gt 0 ] && echo " by GNU parallel -j $jobs") = the $all frames of the unsharded render, each once, byte-identical"
