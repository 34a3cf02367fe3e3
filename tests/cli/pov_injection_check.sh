#!/usr/bin/env bash
# pov_injection_check.sh F2 SCENE OUTDIR: a scene whose directory name holds a
# newline, quotes, `#` and `*/` (issue 29: the path went verbatim into the
# export's first `//` comment, so the rest of the name became live SDL). The
# export's every line outside comments must be f2's own, and with povray
# installed, rendering the export must not run the injected `#fopen`/`#write`.
set -eu
f2=$1 scene=$2 out=$3
. "$(dirname "$0")/../skip.sh"
rm -rf "$out" && mkdir -p "$out"
marker="$out/injected.txt"
dir="$out/x"$'\n'"#fopen F \"$marker\" write #write (F, \"pwned\") #fclose F /* */ \"q\"#"$'\r'"y"
mkdir -p "$dir"
cp "$scene" "$dir/scene.f2"
"$f2" export "$dir/scene.f2" --frame 3 --pov --size 40x30 -o "$out/scene.pov"
"$f2" export "$dir/scene.f2" --frame 3 --prims -o "$out/scene.prims"
# The only directive line is f2's `#version`; the prims list's only `#` line is its header.
directives=$(grep -c '^[[:space:]]*#' "$out/scene.pov" || true)
[ "$directives" = 1 ] || { echo "FAIL: $directives directive lines in the POV-Ray export:"; grep -n '^[[:space:]]*#' "$out/scene.pov"; exit 1; }
grep -q '^#version 3.7;$' "$out/scene.pov" || { echo "FAIL: no #version line"; exit 1; }
grep -qF '\n#fopen F' "$out/scene.pov" || { echo "FAIL: the path is not in the comment, escaped"; head -2 "$out/scene.pov"; exit 1; }
if grep -q $'\r' "$out/scene.pov" "$out/scene.prims"; then echo "FAIL: a carriage return reached the output"; exit 1; fi
headers=$(grep -c '^#' "$out/scene.prims" || true)
[ "$headers" = 1 ] || { echo "FAIL: $headers comment lines in the primitive list"; exit 1; }
command -v povray >/dev/null || skip_missing "povray is not installed (the export itself was checked)"
(cd "$out" && povray +Iscene.pov +Oscene.png +W40 +H30 -A +FN -D 2>povray.log) ||
  { cat "$out/povray.log"; echo "FAIL: povray"; exit 1; }
[ ! -e "$marker" ] || { echo "FAIL: povray ran the injected #fopen/#write"; exit 1; }
echo "OK: the hostile path stays inside the comment; povray rendered the export and ran nothing of it"
