#!/usr/bin/env bash
# pov_compare.sh F2 IMAGE_COMPARE OUTDIR NAME SCENE W H CHECK...: exports
# SCENE (frame 0) to POV-Ray, renders it with povray (no anti-aliasing) and
# with f2 at WxH, and compares the two with `image_compare CHECK...` given the
# background colour, e.g. `match 2 300` (the same coverage, at most 300 pixels
# more than 2 levels apart) or `mean 1.5` (mean absolute difference).
set -eu
f2=$1 compare=$2 out=$3 name=$4 scene=$5 w=$6 h=$7
shift 7
mode=$1
shift
mkdir -p "$out"
"$f2" export "$scene" --pov --size "${w}x$h" -o "$out/$name.pov"
povray "+I$out/$name.pov" "+O$out/${name}_pov.png" "+W$w" "+H$h" -A +FN -D 2>"$out/$name.povlog" ||
  { cat "$out/$name.povlog"; echo "FAIL: povray"; exit 1; }
"$f2" render "$scene" --size "${w}x$h" -o "$out/${name}_f2.png"
# The background colour: the export's `background { rgb <R, G, B> / 255 }`.
read -r r g b < <(sed -n 's/^background { rgb <\([0-9]*\), \([0-9]*\), \([0-9]*\)> .*/\1 \2 \3/p' "$out/$name.pov")
"$compare" "$mode" "$out/${name}_f2.png" "$out/${name}_pov.png" "$r" "$g" "$b" "$@"
