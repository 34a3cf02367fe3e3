#!/usr/bin/env bash
# same_scene_check.sh F2 OUTDIR SCENE...: each first-edition scene renders
# bit-identically when read directly and when read through `/include` inside
# a one-pass `/repeat` (SPEC 9: the second edition changes nothing for them).
set -eu
f2=$1 out=$2
shift 2
mkdir -p "$out"
for scene in "$@"; do
    name=$(basename "$scene" .f2)
    wrapper="$out/wrapped_$name.f2"
    printf '/repeat once 1 1\n/include "%s"\n/end\n' "$(cd "$(dirname "$scene")" && pwd)/$(basename "$scene")" >"$wrapper"
    for frame in 0 50 120; do
        "$f2" render "$scene" --frame $frame --size 160x120 --threads 2 -o "$out/direct_${name}_$frame.png" >/dev/null
        "$f2" render "$wrapper" --frame $frame --size 160x120 --threads 2 -o "$out/wrapped_${name}_$frame.png" >/dev/null
        cmp "$out/direct_${name}_$frame.png" "$out/wrapped_${name}_$frame.png" ||
            { echo "FAIL: $scene frame $frame differs through /include"; exit 1; }
    done
    echo "ok: $scene"
done
