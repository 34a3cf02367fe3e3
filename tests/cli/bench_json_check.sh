#!/usr/bin/env bash
# bench_json_check.sh F2 ARGS...
# Runs `F2 bench ARGS...` and checks that stdout is one JSON object with every
# key docs/performance.md promises and fps > 0. No speed thresholds: machines differ.
set -u
f2=$1
shift
out=$("$f2" bench "$@") || { echo "FAIL: f2 bench exited $?"; exit 1; }
echo "$out"
[ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || { echo "FAIL: expected one line of JSON"; exit 1; }
case $out in "{"*"}") ;; *) echo "FAIL: not a JSON object"; exit 1 ;; esac
if command -v python3 >/dev/null; then
  python3 -c 'import json,sys; json.loads(sys.argv[1])' "$out" || { echo "FAIL: invalid JSON"; exit 1; }
fi
for key in scene size threads frames fps ms_median ms_min ms_max mrays_per_s ms_eval ms_build ms_trace cpu_ms cpu_ms_max bvh_rebuilds bvh_swaps bvh_max_split_work reflected_rays peak_rss_mb lights ms_trace_per_light; do
  grep -q "\"$key\": " <<<"$out" || { echo "FAIL: no key $key"; exit 1; }
done
number() { sed -n "s/.*\"$1\": \([-0-9.e+]*\).*/\1/p" <<<"$out"; }
awk -v fps="$(number fps)" -v frames="$(number frames)" -v rss="$(number peak_rss_mb)" \
  'BEGIN { exit !(fps > 0 && frames >= 3 && rss > 0) }' || { echo "FAIL: fps, frames or peak_rss_mb out of range"; exit 1; }
echo "ok"
