#!/usr/bin/env bash
# pov_blur_check.sh F2 BLUR_COMPARE OUTDIR NAME SCENE FRAME SHUTTER SAMPLES W H BOUND:
# renders SCENE's FRAME with f2 --motion-blur SHUTTER --motion-samples SAMPLES,
# and each of its sub-frames with POV-Ray (from `f2 export --pov` at the
# sub-frame's time, docs/output.md: FRAME + SHUTTER·((i + 0.5)/SAMPLES − 0.5)),
# averages those, and requires f2's frame to be within BOUND levels of that
# mean (mean absolute difference), and much closer than f2's sharp frame.
set -eu
. "$(dirname "$0")/../skip.sh"
command -v povray >/dev/null || skip_missing "povray is not installed (apt-get install povray)"
f2=$1 compare=$2 out=$3 name=$4 scene=$5 frame=$6 shutter=$7 samples=$8 w=$9 h=${10} bound=${11}
mkdir -p "$out"
"$f2" render "$scene" --frame "$frame" --size "${w}x$h" --motion-blur "$shutter" --motion-samples "$samples" \
  -o "$out/${name}_f2.png"
"$f2" render "$scene" --frame "$frame" --size "${w}x$h" -o "$out/${name}_f2_sharp.png"
subs=()
for ((i = 0; i < samples; i++)); do
  t=$(awk -v f="$frame" -v s="$shutter" -v n="$samples" -v i="$i" 'BEGIN { printf "%.17g", f + s * ((i + 0.5) / n - 0.5) }')
  "$f2" export "$scene" --frame "$t" --pov --size "${w}x$h" -o "$out/${name}_$i.pov"
  # povray writes its own messages to stderr; keep them for a failure.
  povray "+I$out/${name}_$i.pov" "+O$out/${name}_pov_$i.png" "+W$w" "+H$h" -A +FN -D 2>"$out/${name}_$i.povlog" ||
    { cat "$out/${name}_$i.povlog"; echo "FAIL: povray at frame $t"; exit 1; }
  subs+=("$out/${name}_pov_$i.png")
done
"$compare" "$out/${name}_f2.png" "$out/${name}_f2_sharp.png" "$bound" "$out/${name}_pov_mean.png" "${subs[@]}"
