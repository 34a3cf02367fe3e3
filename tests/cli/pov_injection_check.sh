#!/usr/bin/env bash
# pov_injection_check.sh F2 SCENE OUTDIR: a scene whose directory name holds a
# newline, quotes, `#` and `*/` (issue 29: the path went verbatim into the
# export's first `//` comment, so the rest of the name became live SDL). The
# export's every line outside comments must be f2's own, and with povray
# installed, rendering the export must not run the injected `#fopen`/`#write`.
# The animation export (--animation) too: its directives are f2's own, its
# .ini holds no line of the path, and a hostile -o name is refused unwritten.
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
"$f2" export "$dir/scene.f2" --pov --animation --size 40x30 -o "$out/anim.pov"
# Its directives: the version, its clock, its arrays, key intervals and visibility tests, nothing else.
others=$(grep '^[[:space:]]*#' "$out/anim.pov" | grep -Evc '^(#version 3\.7;|[ ]*#declare F2_[A-Za-z0-9_]+ = [^"#]*;|#declare F2_[A-Za-z0-9_]+ = array\[[0-9]+\] \{|#if \(F2_Shape[0-9]+_Visible\[F2_K\]\)|#if \(F2_Visible[0-9]+_Position\.x >= 0\.5( & F2_Visible[0-9]+_Position\.x >= 0\.5)*\)|[ ]*#(if|elseif|for) \(F2_[^"#]*\)|[ ]*#else|[ ]*#end)$' || true)
[ "$others" = 0 ] || { echo "FAIL: $others directive lines in the animation export are not f2's"; exit 1; }
grep -q '^#version 3.7;$' "$out/anim.pov" || { echo "FAIL: no #version line in the animation export"; exit 1; }
grep -qF '\n#fopen F' "$out/anim.pov" || { echo "FAIL: the path is not in the animation's comment, escaped"; exit 1; }
# The .ini: comments and f2's own keys only, the path escaped in its comment.
bad=$(grep -Evc '^(;.*|(Input_File_Name|Output_File_Name|Output_File_Type|Width|Height|Antialias|Display|Initial_Frame|Final_Frame|Initial_Clock|Final_Clock)=[A-Za-z0-9._+-]+)$' "$out/anim.ini" || true)
[ "$bad" = 0 ] || { echo "FAIL: $bad lines of the .ini are not f2's"; cat "$out/anim.ini"; exit 1; }
grep -qF '\n#fopen F' "$out/anim.ini" || { echo "FAIL: the path is not in the .ini's comment, escaped"; exit 1; }
# A name that would add .ini options (a newline, `;`, a shell command) is refused, nothing written.
for name in "a"$'\n'"Post_Frame_Command=touch x" "a;b" "a b" '$(touch x)'; do
  if "$f2" export "$dir/scene.f2" --pov --animation -o "$out/$name.pov" 2>"$out/refused.log"; then
    echo "FAIL: the name '$name' was accepted"; exit 1
  fi
  grep -q "letters, digits and ._+- only" "$out/refused.log" || { cat "$out/refused.log"; echo "FAIL: no reason given"; exit 1; }
  [ ! -e "$out/$name.pov" ] && [ ! -e "$out/$name.ini" ] || { echo "FAIL: '$name' was written"; exit 1; }
done
# The only directive line is f2's `#version`; the prims list's only `#` line is its header.
directives=$(grep -c '^[[:space:]]*#' "$out/scene.pov" || true)
[ "$directives" = 1 ] || { echo "FAIL: $directives directive lines in the POV-Ray export:"; grep -n '^[[:space:]]*#' "$out/scene.pov"; exit 1; }
grep -q '^#version 3.7;$' "$out/scene.pov" || { echo "FAIL: no #version line"; exit 1; }
grep -qF '\n#fopen F' "$out/scene.pov" || { echo "FAIL: the path is not in the comment, escaped"; head -2 "$out/scene.pov"; exit 1; }
if grep -q $'\r' "$out/scene.pov" "$out/scene.prims" "$out/anim.pov" "$out/anim.ini"; then echo "FAIL: a carriage return reached the output"; exit 1; fi
headers=$(grep -c '^#' "$out/scene.prims" || true)
[ "$headers" = 1 ] || { echo "FAIL: $headers comment lines in the primitive list"; exit 1; }
command -v povray >/dev/null || skip_missing "povray is not installed (the export itself was checked)"
(cd "$out" && povray +Iscene.pov +Oscene.png +W40 +H30 -A +FN -D 2>povray.log) ||
  { cat "$out/povray.log"; echo "FAIL: povray"; exit 1; }
(cd "$out" && povray anim.ini +SF2 +EF2 2>povray_anim.log) || { cat "$out/povray_anim.log"; echo "FAIL: povray anim.ini"; exit 1; }
[ ! -e "$marker" ] || { echo "FAIL: povray ran the injected #fopen/#write"; exit 1; }
echo "OK: the hostile path stays inside the comments; povray rendered both exports and ran nothing of them"
