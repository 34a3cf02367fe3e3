#!/usr/bin/env bash
# bench_frame_log_check.sh F2 OUT_DIR
# `f2 bench --frames 5 --frame-log FILE` writes a header and one CSV line per
# timed frame, in order, with the times the playback stepped through and what
# the BVH update did. No speed thresholds: machines differ.
set -u
f2=$1 log=$2/frame_log.csv
rm -f "$log"
"$f2" bench --scene robots:20 --step 1 --frame 46 --frames 5 --warmup 0 --threads 2 --size 80x60 --json \
  --frame-log "$log" >/dev/null || { echo "FAIL: f2 bench exited $?"; exit 1; }
[ -f "$log" ] || { echo "FAIL: no $log"; exit 1; }
header=$(head -n 1 "$log")
expected=frame,t,ms,cpu_ms,ms_eval,ms_build,ms_trace,bvh,subtrees_rebuilt,primitives_rebuilt,split_work,sah_growth,minor_faults,major_faults
[ "$header" = "$expected" ] || { echo "FAIL: header '$header'"; exit 1; }
[ "$(wc -l <"$log")" -eq 6 ] || { echo "FAIL: expected 6 lines"; cat "$log"; exit 1; }
# The warm-up frame renders t = 46, so the timed ones are 47, then the loop wraps to 0, 1, 2, 3.
times=$(tail -n +2 "$log" | cut -d, -f1,2 | tr '\n' ' ')
[ "$times" = "0,47.000 1,0.000 2,1.000 3,2.000 4,3.000 " ] || { echo "FAIL: frames and times '$times'"; exit 1; }
tail -n +2 "$log" | awk -F, '$8 !~ /^(refit|subtrees|staged|swapped|rebuilt)$/ || !($3 > 0) { bad = 1 } END { exit bad }' ||
  { echo "FAIL: a line without a BVH action or a positive time"; cat "$log"; exit 1; }
# An unwritable path is an error, not a silent success.
if "$f2" bench --scene robots:2 --frames 3 --warmup 0 --size 8x6 --frame-log "$2/no/such/dir/log.csv" \
  >/dev/null 2>"$2/frame_log.err"; then
  echo "FAIL: wrote into a missing directory"; exit 1
fi
grep -q "cannot write" "$2/frame_log.err" || { echo "FAIL: no error message"; cat "$2/frame_log.err"; exit 1; }
echo "ok"
