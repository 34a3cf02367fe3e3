#!/usr/bin/env bash
# embree_peer_check.sh F2 PEER IMAGE_COMPARE OUTDIR NAME SCENE FRAME W H [PEER OPTIONS...]:
# exports SCENE at FRAME with `f2 export --prims`, renders it with the Embree
# peer and with f2 at WxH, and requires the same image: the same coverage
# (pixel != background) everywhere, and at most one pixel in 10,000 differing
# by more than 2 in a channel (float rounding on a shadow edge).
# SCENE robots:N or spheres:N is a generated scene (f2 bench --write-scene).
set -eu
f2=$1 peer=$2 compare=$3 out=$4 name=$5 scene=$6 frame=$7 w=$8 h=$9
shift 9
mkdir -p "$out"
case $scene in
  robots:*|spheres:*) "$f2" bench --scene "$scene" --write-scene "$out/$name.f2" >/dev/null; scene=$out/$name.f2 ;;
esac
"$f2" export "$scene" --frame "$frame" --prims --size "${w}x$h" -o "$out/$name.prims"
"$peer" "$out/$name.prims" --seconds 0 --warmup 0 --min-frames 1 --out "$out/${name}_peer.png" "$@"
"$f2" render "$scene" --frame "$frame" --size "${w}x$h" -o "$out/${name}_f2.png"
read -r r g b < <(sed -n 's/^background \([0-9]*\) \([0-9]*\) \([0-9]*\)$/\1 \2 \3/p' "$out/$name.prims")
"$compare" match "$out/${name}_f2.png" "$out/${name}_peer.png" "$r" "$g" "$b" 2 $((w * h / 10000))
