#!/usr/bin/env bash
# sequence_check.sh DIR PREFIX FIRST LAST W H: DIR holds exactly the PNG files
# PREFIX%04d.png for frames FIRST..LAST, each a WxH PNG, and nothing else.
set -eu
dir=$1 prefix=$2 first=$3 last=$4 w=$5 h=$6
here=$(dirname "$0")
expected=$(for ((f = first; f <= last; ++f)); do printf '%s%04d.png\n' "$prefix" "$f"; done)
actual=$(ls -A "$dir")
if [ "$expected" != "$actual" ]; then
  echo "FAIL: files in $dir:"; echo "$actual"; echo "expected:"; echo "$expected"; exit 1
fi
for file in $expected; do "$here/png_check.sh" "$dir/$file" "$w" "$h" >/dev/null || { echo "FAIL: $file"; exit 1; }; done
echo "ok: $(echo "$expected" | wc -l) frames ${w}x${h} in $dir"
