#!/usr/bin/env bash
# pov_check.sh F2 IMAGE_COMPARE OUTDIR NAME SCENE FRAME W H [CHECK...]: exports
# SCENE at FRAME to POV-Ray, renders it with povray (no anti-aliasing) and with
# f2 at WxH, and requires the foreground masks (pixel != background) to have
# IoU >= 0.99; with CHECK (e.g. `match 2 300`), also `image_compare CHECK...`.
set -eu
f2=$1 compare=$2 out=$3 name=$4 scene=$5 frame=$6 w=$7 h=$8
shift 8
mkdir -p "$out"
"$f2" export "$scene" --frame "$frame" --pov --size "${w}x$h" -o "$out/$name.pov"
# povray writes its own messages to stderr; keep them for a failure.
povray "+I$out/$name.pov" "+O$out/${name}_pov.png" "+W$w" "+H$h" -A +FN -D 2>"$out/$name.povlog" ||
  { cat "$out/$name.povlog"; echo "FAIL: povray"; exit 1; }
"$f2" render "$scene" --frame "$frame" --size "${w}x$h" -o "$out/${name}_f2.png"
# The background colour: the export's `background { rgb <R, G, B> / 255 }`.
read -r r g b < <(sed -n 's/^background { rgb <\([0-9]*\), \([0-9]*\), \([0-9]*\)> .*/\1 \2 \3/p' "$out/$name.pov")
"$compare" iou "$out/${name}_f2.png" "$out/${name}_pov.png" "$r" "$g" "$b" 0.99
if [ $# -gt 0 ]; then
  mode=$1
  shift
  "$compare" "$mode" "$out/${name}_f2.png" "$out/${name}_pov.png" "$r" "$g" "$b" "$@"
fi
