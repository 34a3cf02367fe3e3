#!/usr/bin/env bash
# pov_animation_check.sh F2 IMAGE_COMPARE OUTDIR NAME SCENE W H [CHECK...]:
# exports SCENE's whole animation to POV-Ray (NAME.pov driven by clock, and
# NAME.ini), has povray render frames 0, the middle one and the last through
# the .ini (+SF/+EF), and requires each to have f2's foreground (IoU >= 0.99,
# as pov_check.sh) against `f2 render --frame k` at WxH; with CHECK (e.g.
# `match 2 300`), also `image_compare CHECK...`. F2_POV_FRAMES="a b c"
# renders those frames instead.
set -eu
f2=$1 compare=$2 out=$3 name=$4 scene=$5 w=$6 h=$7
shift 7
rm -rf "$out" && mkdir -p "$out"
"$f2" export "$scene" --pov --animation --size "${w}x$h" -o "$out/$name.pov"
last=$(sed -n 's/^Final_Frame=//p' "$out/$name.ini")
[ -n "$last" ] || { echo "FAIL: no Final_Frame in $name.ini"; exit 1; }
grep -qx "Width=$w" "$out/$name.ini" && grep -qx "Height=$h" "$out/$name.ini" ||
  { echo "FAIL: $name.ini does not say ${w}x$h"; cat "$out/$name.ini"; exit 1; }
read -r r g b < <(sed -n 's/^background { rgb <\([0-9]*\), \([0-9]*\), \([0-9]*\)> .*/\1 \2 \3/p' "$out/$name.pov")
for k in ${F2_POV_FRAMES:-0 $((last / 2)) $last}; do
  # POV-Ray pads the frame number to the digits of the last frame.
  png=$(printf "%s_%0${#last}d.png" "$name" "$k")
  (cd "$out" && povray "$name.ini" "+SF$k" "+EF$k" 2>"$name.povlog") ||
    { cat "$out/$name.povlog"; echo "FAIL: povray at frame $k"; exit 1; }
  [ -s "$out/$png" ] || { echo "FAIL: povray wrote no $png"; ls "$out"; exit 1; }
  "$f2" render "$scene" --frame "$k" --size "${w}x$h" -o "$out/f2_$k.png"
  echo "frame $k:"
  "$compare" iou "$out/f2_$k.png" "$out/$png" "$r" "$g" "$b" 0.99
  if [ $# -gt 0 ]; then "$compare" "$1" "$out/f2_$k.png" "$out/$png" "$r" "$g" "$b" "${@:2}"; fi
done
