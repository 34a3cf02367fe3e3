#!/usr/bin/env bash
# Checks the layering of the code (docs/design.md, "Layers"):
#  1. every #include "core/<folder>/..." points down a layer or within its own
#     folder, never up and never sideways, so the folders form no cycle;
#  2. SIMD types stay private: a core header that includes core/simd/, directly
#     or through another header, is private, and the front ends (src/io, apps,
#     lsp, fuzz, and the viewer's and language server's tests, built without
#     the core's CPU flags) include no private header;
#  3. with a compiler given (CXX=...), every public core header compiles on its
#     own without any -m flag and with the project's warnings.
# Exit 1 with one line per finding; 0 when the tree is clean.
#
# Usage: scripts/check-layers.sh [CXX]
set -euo pipefail
cd "$(dirname "$0")/.."
cxx="${1:-}"

# Rank of each layer: a file may include headers of lower-ranked layers and of
# its own folder. Folders of equal rank are independent of each other.
declare -A rank=(
  [core/util]=0 [core/simd]=0
  [core/math]=1
  [core/geometry]=2
  [core/scene]=3
  [core/parse]=4 [core/anim]=4
  [core/render]=5
  [io]=6 [lsp]=6
  [apps]=7
)

failures=0
fail() {
  echo "check-layers: $*"
  failures=$((failures + 1))
}

# Layer of a repository path (src/core/x/..., src/io/..., apps/...), or empty.
layer_of_file() {
  case "$1" in
    src/core/*/*) local rest=${1#src/core/}; echo "core/${rest%%/*}" ;;
    src/io/*) echo io ;;
    src/lsp/*) echo lsp ;;
    apps/*) echo apps ;;
  esac
}
# Layer of an include path ("core/x/y.h", "io/y.h"), or empty (own folder, system).
layer_of_include() {
  case "$1" in
    core/*/*) local rest=${1#core/}; echo "core/${rest%%/*}" ;;
    io/*) echo io ;;
    lsp/*) echo lsp ;;
  esac
}

# C++ sources under the given folders, sorted.
sources() { find "$@" -type f \( -name '*.h' -o -name '*.cpp' \) | sort; }

# Includes of a file, one per line: quoted ones, and project headers in <>.
includes_of() {
  sed -n -e 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' \
    -e 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*<\(\(core\|io\|lsp\)\/[^>]*\)>.*/\1/p' "$1"
}

# 1. Layers: no include up or sideways; the folder graph has no cycle.
edges=$(mktemp)
trap 'rm -f "$edges"' EXIT
while IFS= read -r file; do
  from=$(layer_of_file "$file")
  [[ -n "$from" ]] || continue
  if [[ -z "${rank[$from]+set}" ]]; then
    fail "$file: folder $from has no layer: add it to scripts/check-layers.sh and docs/design.md"
    continue
  fi
  while IFS= read -r inc; do
    if [[ "$inc" == *../* ]]; then
      fail "$file: includes \"$inc\": name project headers from src/ (\"core/x/y.h\"), not by a relative path"
      continue
    fi
    to=$(layer_of_include "$inc")
    [[ -n "$to" && "$to" != "$from" ]] || continue
    if [[ -z "${rank[$to]+set}" ]]; then
      fail "$file: includes \"$inc\" from folder $to, which has no layer"
    elif (( rank[$to] >= rank[$from] )); then
      what=up; (( rank[$to] == rank[$from] )) && what=sideways
      fail "$file: includes \"$inc\": $from (layer ${rank[$from]}) may not include $what into $to (layer ${rank[$to]})"
    fi
    echo "$from $to" >> "$edges"
  done < <(includes_of "$file")
done < <(sources src apps)
sort -u -o "$edges" "$edges"
if ! tsort "$edges" > /dev/null 2>&1; then
  loop=$(tsort "$edges" 2>&1 >/dev/null | sed -n 's/^tsort: \(core\/[a-z_]*\|io\|lsp\|apps\)$/\1/p' | sort -u | tr '\n' ' ' || true)
  fail "the folders include each other in a cycle through: $loop"
fi

# 2. SIMD stays private: mark every core header that reaches core/simd/.
declare -A private=()
core_headers=$(sources src/core | grep '\.h$')
for h in $core_headers; do
  [[ $h == src/core/simd/* ]] && private[${h#src/}]=1
done
changed=1
while (( changed )); do
  changed=0
  for h in $core_headers; do
    key=${h#src/}
    [[ -z "${private[$key]:-}" ]] || continue
    while IFS= read -r inc; do
      if [[ -n "${private[$inc]:-}" ]]; then
        private[$key]=1
        changed=1
        break
      fi
    done < <(includes_of "$h")
  done
done
while IFS= read -r file; do
  while IFS= read -r inc; do
    if [[ -n "${private[$inc]:-}" ]]; then
      fail "$file: includes \"$inc\", a private core header (it reaches core/simd/, whose types depend on -march)"
    fi
  done < <(includes_of "$file")
done < <(sources src/io src/lsp apps fuzz tests/viewer tests/lsp)

# 3. Public headers compile alone, with no CPU flag.
if [[ -n "$cxx" ]]; then
  tu=$(mktemp --suffix=.cpp)
  trap 'rm -f "$edges" "$tu"' EXIT
  for h in $core_headers; do
    key=${h#src/}
    [[ -z "${private[$key]:-}" ]] || continue
    printf '#include "%s"\n' "$key" > "$tu"
    if ! out=$("$cxx" -std=c++20 -fsyntax-only -Wall -Wextra -Werror -Isrc "$tu" 2>&1); then
      fail "$key does not compile on its own without CPU flags:"
      echo "$out" | head -n 5
    fi
  done
fi

if (( failures )); then
  echo "check-layers: $failures problem(s)"
  exit 1
fi
echo "check-layers: ok (${#rank[@]} layers, ${#private[@]} private SIMD headers)"
