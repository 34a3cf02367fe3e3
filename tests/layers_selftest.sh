#!/usr/bin/env bash
# layers_selftest.sh: scripts/check-layers.sh really fails on what it is
# there to catch. Each case is a small tree beside a copy of the script (it
# checks the tree it stands in): a clean one must pass; a cycle between two
# folders, an include up (also in <> or by a relative path), one sideways, and a
# front end reaching a SIMD header through a core header must each fail with
# their message.
set -euo pipefail
script=$(cd "$(dirname "$0")/.." && pwd)/scripts/check-layers.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0

# tree NAME FILE=INCLUDES... : a tree whose FILE includes each of INCLUDES (comma-separated).
tree() {
  local dir=$work/$1
  shift
  mkdir -p "$dir/scripts"
  cp "$script" "$dir/scripts/"
  for spec in "$@"; do
    local file=${spec%%=*} includes=${spec#*=}
    mkdir -p "$dir/$(dirname "$file")"
    : > "$dir/$file"
    IFS=, read -ra list <<< "$includes"
    for inc in "${list[@]}"; do [[ -z "$inc" ]] || echo "#include \"$inc\"" >> "$dir/$file"; done
  done
  echo "$dir"
}

# expect NAME EXIT REGEX TREE: runs the script in TREE; its exit code and output must match.
expect() {
  local name=$1 code=$2 regex=$3 dir=$4 out rc=0
  out=$("$dir/scripts/check-layers.sh" 2>&1) || rc=$?
  if [[ $rc -ne $code ]] || ! grep -Eq "$regex" <<< "$out"; then
    echo "FAIL: $name: exit $rc (expected $code), output:"
    sed 's/^/  /' <<< "$out"
    failed=$((failed + 1))
  else
    echo "ok: $name"
  fi
}

base=(src/core/util/pool.h= src/core/math/vec.h=core/util/pool.h
      src/core/geometry/bvh.h=core/math/vec.h src/core/render/renderer.h=core/geometry/bvh.h
      src/core/simd/lanes.h= src/core/geometry/packet.h=core/simd/lanes.h
      apps/cli/main.cpp=core/render/renderer.h)

expect "a clean tree passes" 0 "check-layers: ok" "$(tree clean "${base[@]}")"
expect "a cycle between two folders fails" 1 "cycle through: .*core/geometry.*core/render" \
  "$(tree cycle "${base[@]}" src/core/geometry/back.h=core/render/renderer.h)"
expect "an include up fails" 1 "core/math \(layer 1\) may not include up into core/geometry" \
  "$(tree up "${base[@]}" src/core/math/up.h=core/geometry/bvh.h)"
expect "an include sideways fails" 1 "may not include sideways" \
  "$(tree sideways "${base[@]}" src/core/anim/a.h=core/parse/p.h src/core/parse/p.h=)"
expect "a relative include fails" 1 "not by a relative path" \
  "$(tree relative "${base[@]}" src/core/math/rel.h=../geometry/bvh.h)"
angle=$(tree angle "${base[@]}")
echo '#include <core/render/renderer.h>' > "$angle/src/core/util/angle.h"
expect "an include up in <> fails" 1 "core/util \(layer 0\) may not include up into core/render" "$angle"
expect "a front end reaching SIMD through a core header fails" 1 \
  "apps/cli/main.cpp: includes \"core/render/renderer.h\", a private core header" \
  "$(tree simd "${base[@]}" src/core/render/renderer.h=core/geometry/bvh.h,core/geometry/packet.h)"

(( failed == 0 )) || { echo "layers_selftest: $failed case(s) failed"; exit 1; }
echo "layers_selftest: check-layers.sh catches cycles, includes up or sideways, and SIMD in public headers"
