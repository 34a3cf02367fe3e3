#!/usr/bin/env bash
# compare_peers.sh — f2 against the Embree peer (bench/embree_peer) and POV-Ray 3.7
# on the same frames, in the same run (docs/performance.md).
#
#   scripts/compare_peers.sh [--f2 PATH] [--threads N] [--frame T] [--seconds S]
#                            [--scenes "default robots:1 ..."] [--pov-scenes "default ..."]
#                            [--rebuild "low medium high refit"] [--rounds R] [--no-embree] [--no-pov]
#                            [--work DIR]
#
# For every scene: `f2 bench --json` times the whole frame (evaluate + build +
# trace); `f2 export --prims` writes that very frame for the peer, which then
# runs once per --rebuild mode (a BVH update every frame, as f2 does); the
# table shows the best of those modes and the ratio f2 FPS / Embree FPS. Both
# time --seconds per run after a warm-up and report the median frame. The
# peer is built from this repository (CMake target f2_embree_peer, in f2's
# build directory or in build/peers; Debian's libembree-dev and libtbb-dev are
# installed if missing).
# --rounds R (default 1) then runs f2 and the peer's best mode R-1 more times,
# one after the other, and shows the medians and the range of the R ratios: on
# a shared machine whose speed drifts for a minute at a time, the ratio of two
# back-to-back runs is steadier than either figure alone.
# When the scenes include robots:1 and larger robots:N, a "Scaling" line gives
# each renderer's frame time of robots:N over robots:1 (the issue's 2.5x goal).
# POV-Ray renders `f2 export --pov` of the frame with -A +WT2; its reported
# "Trace Time" is divided by f2's median frame time.
# Generated scenes (robots:N, spheres:N) reach export through
# `f2 bench --scene X --write-scene FILE`.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)

F2=${F2:-}
THREADS=2
FRAME=0
SECONDS_PER_RUN=3
SCENES="default robots:1 robots:1000 robots:10000 robots:100000 spheres:1000"
POV_SCENES="default"
REBUILD_MODES="low medium high refit"
ROUNDS=1
RUN_EMBREE=1
RUN_POV=1
WORK=$ROOT/build/peers/work
SIZE=800x600

usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
while [ $# -gt 0 ]; do
  case $1 in
    --f2) F2=$2; shift ;;
    --threads) THREADS=$2; shift ;;
    --frame) FRAME=$2; shift ;;
    --seconds) SECONDS_PER_RUN=$2; shift ;;
    --scenes) SCENES=$2; shift ;;
    --pov-scenes) POV_SCENES=$2; shift ;;
    --rebuild) REBUILD_MODES=$2; shift ;;
    --rounds) ROUNDS=$2; shift ;;
    --no-embree) RUN_EMBREE=0 ;;
    --no-pov) RUN_POV=0 ;;
    --work) WORK=$2; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "compare_peers: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
  shift
done

log() { echo "compare_peers: $*" >&2; }
as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

# --- f2: an existing optimised build, else build the headless preset ----------
if [ -z "$F2" ]; then
  for dir in build/release build/headless build/bench; do
    if [ -x "$ROOT/$dir/apps/cli/f2" ]; then F2=$ROOT/$dir/apps/cli/f2; break; fi
  done
fi
if [ -z "$F2" ]; then
  log "no f2 binary found; building the headless preset"
  (cd "$ROOT" && cmake --preset headless >/dev/null && cmake --build --preset headless --target f2)
  F2=$ROOT/build/headless/apps/cli/f2
fi
"$F2" export --help >/dev/null 2>&1 || { log "$F2 has no 'export' command yet"; exit 1; }
mkdir -p "$WORK"
log "f2: $F2"

# --- the Embree peer: bench/embree_peer, built from this repository -------------
# In f2's own build directory when f2 came from one and it has the target (the
# same sources, no second build of the core), else in build/peers.
PEER=
if [ "$RUN_EMBREE" = 1 ]; then
  if ! dpkg -s libembree-dev libtbb-dev >/dev/null 2>&1; then
    log "installing libembree-dev libtbb-dev"
    as_root apt-get install -y libembree-dev libtbb-dev >&2
  fi
  case $F2 in
    "$ROOT"/build/*/apps/cli/f2)
      dir=${F2%/apps/cli/f2}
      if cmake --build "$dir" --target f2_embree_peer >&2 2>/dev/null; then PEER=$dir/bench/embree_peer/f2_embree_peer; fi ;;
  esac
  if [ -z "$PEER" ]; then
    PEER_BUILD=$ROOT/build/peers
    if ! [ -f "$PEER_BUILD/CMakeCache.txt" ]; then
      cmake -S "$ROOT" -B "$PEER_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DF2_BUILD_EMBREE_PEER=ON \
        -DF2_BUILD_VIEWER=OFF -DF2_BUILD_TESTS=OFF -DF2_BUILD_BENCH=OFF >&2
    fi
    cmake --build "$PEER_BUILD" --target f2_embree_peer >&2
    PEER=$PEER_BUILD/bench/embree_peer/f2_embree_peer
  fi
  log "peer: $PEER"
fi

# value KEY JSON|RESULT-line: the number after "KEY": or KEY=
json_value() { sed -n "s/.*\"$1\": \([-0-9.e+]*\).*/\1/p" <<<"$2"; }
result_value() { tr ' ' '\n' <<<"$2" | sed -n "s/^$1=//p"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "n/a" }'; }
# median of the numbers on stdin (one per line)
median() { sort -g | awk '{ v[NR] = $1 } END { if (NR == 0) print "n/a"; else if (NR % 2) print v[(NR + 1) / 2]; else printf "%.2f\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# scene_file SCENE: the scene as a file export can read ("" = the default scene)
scene_file() {
  case $1 in
    default) echo "" ;;
    robots:*|spheres:*)
      local file="$WORK/${1/:/_}.f2"
      "$F2" bench --scene "$1" --size "$SIZE" --write-scene "$file" 2>/dev/null
      echo "$file" ;;
    *) echo "$1" ;;
  esac
}

# f2_bench SCENE: JSON of f2 bench on it
f2_bench() {
  case $1 in
    default) "$F2" bench --frame "$FRAME" --size "$SIZE" --threads "$THREADS" --seconds "$SECONDS_PER_RUN" --json ;;
    robots:*|spheres:*) "$F2" bench --scene "$1" --frame "$FRAME" --size "$SIZE" --threads "$THREADS" \
                          --seconds "$SECONDS_PER_RUN" --json ;;
    *) "$F2" bench "$1" --frame "$FRAME" --size "$SIZE" --threads "$THREADS" --seconds "$SECONDS_PER_RUN" --json ;;
  esac
}

echo "## f2 vs peers, $SIZE, $THREADS threads, frame $FRAME"
echo
echo "$(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, load average $(cut -d' ' -f1 /proc/loadavg), f2 = $F2"
echo

if [ "$RUN_EMBREE" = 1 ]; then
  echo "### Embree peer (whole frame, BVH updated every frame; best of --rebuild $REBUILD_MODES)"
  echo
  [ "$ROUNDS" -gt 1 ] && echo "Medians of $ROUNDS rounds (f2, then Embree in its best mode); the f2 split and the static figure are the first round's; last column: the rounds' ratios, lowest to highest." && echo
  echo "| Scene | Primitives | f2 FPS | f2 ms (eval / build / trace) | Embree FPS | Embree mode | Embree static FPS | f2 / Embree |$([ "$ROUNDS" -gt 1 ] && echo " ratios |")"
  echo "|---|---:|---:|---|---:|---|---:|---:|$([ "$ROUNDS" -gt 1 ] && echo "---|")"
  declare -A f2_median embree_median
  for scene in $SCENES; do
    file=$(scene_file "$scene")
    prims=$WORK/${scene/:/_}.prims
    "$F2" export ${file:+"$file"} --frame "$FRAME" --size "$SIZE" --prims -o "$prims" 2>/dev/null
    log "$scene: f2 bench"
    json=$(f2_bench "$scene")
    f2_fps=$(json_value fps "$json")
    split="$(json_value ms_median "$json") ($(json_value ms_eval "$json") / $(json_value ms_build "$json") / $(json_value ms_trace "$json"))"
    best_fps=0 best_mode=none
    for mode in $REBUILD_MODES; do
      log "$scene: f2_embree_peer --rebuild $mode"
      line=$("$PEER" "$prims" --threads "$THREADS" --seconds "$SECONDS_PER_RUN" --rebuild "$mode" | grep '^RESULT')
      fps=$(result_value total_fps "$line")
      if awk -v a="$fps" -v b="$best_fps" 'BEGIN { exit !(a > b) }'; then best_fps=$fps best_mode=$mode; fi
    done
    # Render-only yardstick: static BVH built once (not what an animation can do).
    static=$(result_value fps "$("$PEER" "$prims" --threads "$THREADS" --seconds "$SECONDS_PER_RUN" | grep '^RESULT')")
    f2_all=$f2_fps embree_all=$best_fps ratios=$(ratio "$f2_fps" "$best_fps")
    for ((round = 2; round <= ROUNDS; ++round)); do
      log "$scene: round $round of $ROUNDS"
      f=$(json_value fps "$(f2_bench "$scene")")
      e=$(result_value total_fps "$("$PEER" "$prims" --threads "$THREADS" --seconds "$SECONDS_PER_RUN" --rebuild "$best_mode" | grep '^RESULT')")
      f2_all+=$'\n'$f embree_all+=$'\n'$e ratios+=$'\n'$(ratio "$f" "$e")
    done
    f2_median[$scene]=$(median <<<"$f2_all") embree_median[$scene]=$(median <<<"$embree_all")
    row="| $scene | $(json_value primitives "$json") | ${f2_median[$scene]} | $split | ${embree_median[$scene]} | $best_mode | $static | $(median <<<"$ratios") |"
    [ "$ROUNDS" -gt 1 ] && row+=" $(sort -g <<<"$ratios" | paste -sd' ') |"
    echo "$row"
  done
  echo
  # Issue 4's scaling target: N robots within 2.5x the frame time of one robot.
  if [ -n "${f2_median[robots:1]:-}" ]; then
    for scene in $SCENES; do
      case $scene in robots:1|robots:*[!0-9]*) continue ;; robots:*) ;; *) continue ;; esac
      [ -n "${f2_median[$scene]:-}" ] || continue
      echo "Scaling, frame time of $scene / robots:1 (target <= 2.5): f2 $(ratio "${f2_median[robots:1]}" "${f2_median[$scene]}"), Embree $(ratio "${embree_median[robots:1]}" "${embree_median[$scene]}")"
    done
    echo
  fi
fi

if [ "$RUN_POV" = 1 ]; then
  if ! command -v povray >/dev/null; then
    log "povray not found (apt-get install povray); skipping the POV-Ray comparison"
  else
    echo "### POV-Ray 3.7 (povray -A +WT2, its reported Trace Time) vs f2's whole frame"
    echo
    echo "| Scene | POV-Ray trace ms | f2 frame ms | POV-Ray / f2 |"
    echo "|---|---:|---:|---:|"
    for scene in $POV_SCENES; do
      file=$(scene_file "$scene")
      pov=$WORK/${scene/:/_}.pov
      "$F2" export ${file:+"$file"} --frame "$FRAME" --size "$SIZE" --pov -o "$pov" 2>/dev/null
      log "$scene: povray"
      w=${SIZE%x*} h=${SIZE#*x}
      err=$( (cd "$WORK" && povray +I"$pov" +O"$WORK/pov_out.png" +W"$w" +H"$h" -A +WT2 +FN -D) 2>&1 >/dev/null) || true
      # "  Trace Time:       0 hours  0 minutes  0 seconds (0.171 seconds)"
      pov_s=$(sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' <<<"$err" | tail -1)
      if [ -z "$pov_s" ]; then log "$scene: no 'Trace Time' in povray's output"; continue; fi
      pov_ms=$(awk -v s="$pov_s" 'BEGIN { printf "%.1f", s * 1000 }')
      log "$scene: f2 bench"
      f2_ms=$(json_value ms_median "$(f2_bench "$scene")")
      echo "| $scene | $pov_ms | $f2_ms | $(ratio "$pov_ms" "$f2_ms") |"
    done
    echo
  fi
fi
