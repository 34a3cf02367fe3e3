#!/usr/bin/env bash
# gltf_check.sh validator|three F2 WORK SCENE...: `f2 export --gltf` of each
# scene, then
#   validator: the Khronos glTF validator (npm gltf-validator) must report 0
#     errors and 0 warnings on every .glb, and on the first scene written as
#     .gltf + .bin at another --tessellation, under a name with a space, `#`,
#     a quote, `%` and a non-ASCII letter, and on every scene exported with
#     --gltf-pointer;
#   three: three.js (npm three, GLTFLoader + AnimationMixer) must place every
#     shape and the camera where `f2 export --prims` does at 0 s, 1.03 s
#     (between frames), 2.5 s and the last frame (tests/gltf/three_check.mjs);
#   blender: Blender (headless, its own glTF importer) must place every shape
#     and the camera where `f2 export --prims` does at frames 0, 60, 120 and
#     the last, with F2's field of view, fps and frame range
#     (tests/gltf/blender_check.py).
# Skipped (tests/skip.sh) without node or the npm packages of tests/gltf
# (scripts/install-node-packages.sh installs them), or, for blender, without
# Blender (scripts/install-deps.sh installs it).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../skip.sh"
mode=$1 f2=$2 work=$3
shift 3
pkg=$(cd "$here/../gltf" && pwd)
if [ "$mode" = blender ]; then
  command -v blender >/dev/null 2>&1 || skip_missing "blender is not installed (scripts/install-deps.sh installs it)"
else
  command -v node >/dev/null 2>&1 || skip_missing "node is not installed (scripts/install-deps.sh installs nodejs and npm)"
  for p in gltf-validator three; do
    [ -d "$pkg/node_modules/$p" ] ||
      skip_missing "npm package $p is missing in tests/gltf: run scripts/install-node-packages.sh (scripts/test.sh does)"
  done
fi
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work" && mkdir -p "$work/text"

files=()
for scene in "$@"; do
  glb=$work/$(basename "$scene" .f2).glb
  "$f2" export "$scene" --gltf -o "$glb" || fail "f2 export --gltf $scene"
  files+=("$glb")
done
case $mode in
  validator)
    # A name that a URI must escape: the .gltf still finds its .bin.
    text="$work/text/a b#\"%é $(basename "$1" .f2).gltf"
    "$f2" export "$1" --gltf --tessellation 12 -o "$text" || fail "f2 export --gltf $1 -o .gltf"
    [ -s "${text%.gltf}.bin" ] || fail "no .bin beside $text"
    # Every scene again with colour, intensity and d keys as KHR_animation_pointer channels.
    pointers=()
    for scene in "$@"; do
      pointer=$work/pointer/$(basename "$scene" .f2).glb
      mkdir -p "$work/pointer"
      "$f2" export "$scene" --gltf --gltf-pointer -o "$pointer" 2>/dev/null || fail "f2 export --gltf-pointer $scene"
      pointers+=("$pointer")
    done
    ls -l "${files[@]}" "$text" "${text%.gltf}.bin"
    (cd "$pkg" && node validate.mjs "${files[@]}" "$text" "${pointers[@]}") ||
      fail "the validator found errors or warnings"
    ;;
  three)
    i=0
    for scene in "$@"; do
      (cd "$pkg" && node three_check.mjs "$f2" "$scene" "${files[$i]}" 0 1.03 2.5 last) ||
        fail "three.js does not see $scene as f2 does"
      i=$((i + 1))
    done
    ;;
  blender)
    i=0
    for scene in "$@"; do
      # --python-exit-code: a failing check is Blender's exit code too.
      blender -b --factory-startup --python-exit-code 1 --python "$pkg/blender_check.py" -- \
        "$f2" "$scene" "${files[$i]}" 0 60 120 last > "$work/blender.log" 2>&1
      status=$?
      grep -E "^FAIL|: [0-9]+ fps|shapes and the camera|Error|Traceback" "$work/blender.log"
      [ $status -eq 0 ] || fail "Blender does not see $scene as f2 does (exit $status; $work/blender.log)"
      i=$((i + 1))
    done
    ;;
  *) fail "unknown mode $mode" ;;
esac
echo ok
