#!/usr/bin/env bash
# ab_pairs.sh — compare two f2 binaries by interleaved pairs (docs/performance.md §5).
#
#   scripts/ab_pairs.sh OLD_F2 NEW_F2 [--pairs P] [--seconds S] [--threads N] [--scene X] [-- BENCH_ARGS...]
#
# Runs `f2 bench --json` with OLD then NEW, P times (default 8), and prints
# each pair's FPS and NEW/OLD ratio, then the median ratio and its range; the
# same for the CPU time per frame (`cpu_ms`, old/new, so > 1 is faster), which
# a loaded machine disturbs less than wall time (best with --threads 1). On
# a shared machine whose speed drifts for a minute at a time, the ratio of two
# back-to-back runs is far steadier than either figure. --scene takes what
# `f2 bench --scene` takes (robots:N, spheres:N); "default" is the embedded scene.
set -euo pipefail

usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
[ $# -ge 2 ] || { usage >&2; exit 2; }
OLD=$1 NEW=$2
shift 2
PAIRS=8 SECONDS_PER_RUN=0.6 THREADS=2 SCENE=robots:10000
EXTRA=()
while [ $# -gt 0 ]; do
  case $1 in
    --pairs) PAIRS=$2; shift ;;
    --seconds) SECONDS_PER_RUN=$2; shift ;;
    --threads) THREADS=$2; shift ;;
    --scene) SCENE=$2; shift ;;
    --) shift; EXTRA=("$@"); break ;;
    -h|--help) usage; exit 0 ;;
    *) echo "ab_pairs: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
  shift
done

# bench BINARY: "FPS CPU_MS" of one run (CPU_MS "n/a" for a binary without it)
bench() {
  local scene=() json
  [ "$SCENE" = default ] || scene=(--scene "$SCENE")
  json=$("$1" bench "${scene[@]}" --threads "$THREADS" --seconds "$SECONDS_PER_RUN" --warmup 0.2 --json ${EXTRA[@]+"${EXTRA[@]}"})
  echo "$(sed -n 's/.*"fps": \([0-9.]*\).*/\1/p' <<<"$json") $(sed -n 's/.*"cpu_ms": \([0-9.]*\).*/\1/p' <<<"$json" | grep . || echo n/a)"
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b + 0 > 0) printf "%.3f", a / b; else print "n/a" }'; }
summary() {
  grep -v n/a | sort -g | awk -v what="$1" '{ v[NR] = $1 } END {
    if (NR == 0) { print what ": n/a"; exit }
    m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
    printf "%s %.3f (range %.3f..%.3f, %d pairs)\n", what, m, v[1], v[NR], NR }'
}

echo "# $SCENE, $THREADS threads, $PAIRS pairs of ${SECONDS_PER_RUN} s; load average $(cut -d' ' -f1-3 /proc/loadavg)"
fps_ratios=() cpu_ratios=()
for ((i = 1; i <= PAIRS; ++i)); do
  read -r fa ca <<<"$(bench "$OLD")"
  read -r fb cb <<<"$(bench "$NEW")"
  fps_ratios+=("$(ratio "$fb" "$fa")") cpu_ratios+=("$(ratio "$ca" "$cb")")
  echo "pair $i: old $fa FPS $ca cpu ms, new $fb FPS $cb cpu ms; FPS new/old ${fps_ratios[-1]}, CPU old/new ${cpu_ratios[-1]}"
done
printf '%s\n' "${fps_ratios[@]}" | summary "median FPS new/old"
printf '%s\n' "${cpu_ratios[@]}" | summary "median CPU old/new"
