#!/usr/bin/env bash
# png_check.sh FILE WIDTH HEIGHT: FILE is a PNG of that size and no temporary
# file of it is left beside it. (Its content is checked by image_compare colours.)
set -eu
file=$1 w=$2 h=$3
[ -s "$file" ] || { echo "FAIL: $file missing"; exit 1; }
head -c 8 "$file" | od -An -tx1 | grep -q "89 50 4e 47 0d 0a 1a 0a" || { echo "FAIL: not a PNG"; exit 1; }
dims=$(od -An -tu1 -j16 -N8 "$file" | awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}')
[ "$dims" = "$w $h" ] || { echo "FAIL: size $dims, expected $w $h"; exit 1; }
# Only this file's own temporary: other tests write beside it at the same time.
compgen -G "$file.tmp-*" >/dev/null && { echo "FAIL: temporary file left"; exit 1; }
echo "ok: $file is ${w}x${h}"
