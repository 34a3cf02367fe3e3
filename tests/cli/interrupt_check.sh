#!/usr/bin/env bash
# interrupt_check.sh SIGNAL OUTPUT F2 ARGS...: starts `F2 ARGS... -o OUTPUT`,
# sends SIGNAL (INT or TERM) once rendering is under way, and checks that f2
# exits with 128+signal, leaves no temporary file and (for a video) no output
# at all, or (for a sequence, OUTPUT containing %04d) only complete frames,
# fewer than all of them.
set -u
sig=$1 output=$2
shift 2
dir=$(dirname "$output")
rm -rf "$dir" && mkdir -p "$dir"
"$@" -o "$output" 2>"$dir/stderr.txt" &
pid=$!
# Under way: a video's temporary file exists, or two frames of a sequence are written.
for ((i = 0; i < 200; ++i)); do
  if [[ "$output" == *%* ]]; then [ "$(ls "$dir" | grep -c '\.png$')" -ge 2 ] && break
  else ls "$dir" | grep -q '\.tmp-' && break; fi
  sleep 0.05
done
sleep 0.2
kill -s "$sig" "$pid"
wait "$pid"
code=$?
cat "$dir/stderr.txt"
want=$((128 + $(kill -l "$sig")))
[ "$code" -eq "$want" ] || { echo "FAIL: exit $code, expected $want (was it still running?)"; exit 1; }
grep -q "interrupted" "$dir/stderr.txt" || { echo "FAIL: no 'interrupted' message"; exit 1; }
ls -a "$dir" | grep '\.tmp-' && { echo "FAIL: temporary file left"; exit 1; }
if [[ "$output" == *%* ]]; then
  n=$(ls "$dir" | grep -c '\.png$')
  [ "$n" -ge 2 ] || { echo "FAIL: only $n frames"; exit 1; }
  grep -q "after $n of " "$dir/stderr.txt" || { echo "FAIL: message does not count $n frames"; exit 1; }
  for f in "$dir"/*.png; do
    # A complete PNG ends with its IEND chunk.
    tail -c 8 "$f" | od -An -tx1 | grep -q "49 45 4e 44 ae 42 60 82" || { echo "FAIL: $f is truncated"; exit 1; }
  done
  echo "ok: $n complete frames kept"
else
  [ -e "$output" ] && { echo "FAIL: $output was written"; exit 1; }
  pgrep -f "$(basename "$output")\.tmp-" && { echo "FAIL: ffmpeg still running"; exit 1; }
  echo "ok: no video, no temporary file"
fi
exit 0
