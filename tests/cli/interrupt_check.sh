#!/usr/bin/env bash
# interrupt_check.sh SIGNAL OUTPUT F2 ARGS...: starts `F2 ARGS... -o OUTPUT`,
# sends SIGNAL (INT, TERM or HUP) once two frames are finished, and checks that f2
# exits with 128+signal, leaves no temporary file and (for a video) no output
# at all, or (for a sequence, OUTPUT containing %04d) only complete frames,
# fewer than all of them.
# Deterministic: f2's test handshake (apps/cli/test_pause.h) creates a file
# after frame 2 and then waits for the signal, so the signal always arrives
# mid-animation however loaded the machine is.
# SIGNAL nohup: f2 starts with SIGHUP ignored (as under nohup); a SIGHUP must
# not stop it, so the SIGTERM sent after it is what ends it (143).
set -u
. "$(dirname "$0")/../skip.sh"
sig=$1 output=$2
shift 2
ignore_hup=0
if [ "$sig" = nohup ]; then ignore_hup=1 sig=TERM; fi
if [ "$sig" = HUP ] && (($(printf '%d' "0x$(awk '/^SigIgn/ {print $2}' /proc/$$/status)") & 1)); then
  skip_impossible "SIGHUP is ignored in this test's environment (started under nohup?)"
fi
dir=$(dirname "$output")
rm -rf "$dir" && mkdir -p "$dir"
paused="$dir/paused"
export F2_TEST_PAUSE_AFTER_FRAMES=2 F2_TEST_PAUSE_FILE="$paused"
if [ "$ignore_hup" = 1 ]; then
  (trap '' HUP && exec "$@" -o "$output" 2>"$dir/stderr.txt") &
else
  "$@" -o "$output" 2>"$dir/stderr.txt" &
fi
pid=$!
# Waiting for a condition, not for a time: f2 holds still once it is true.
until [ -e "$paused" ]; do
  kill -0 "$pid" 2>/dev/null || { cat "$dir/stderr.txt"; echo "FAIL: f2 ended before frame 2"; exit 1; }
  sleep 0.02
done
[ "$ignore_hup" = 1 ] && kill -s HUP "$pid"  # ignored: f2 keeps waiting for the signal below
kill -s "$sig" "$pid"
wait "$pid"
code=$?
rm -f "$paused"
cat "$dir/stderr.txt"
want=$((128 + $(kill -l "$sig")))
[ "$code" -eq "$want" ] || { echo "FAIL: exit $code, expected $want"; exit 1; }
grep -q "interrupted" "$dir/stderr.txt" || { echo "FAIL: no 'interrupted' message"; exit 1; }
ls -a "$dir" | grep '\.tmp' && { echo "FAIL: temporary file left"; exit 1; }
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
  # ffmpeg's output is file:ABSOLUTE-PATH.tmp-XXXXXX: matched by the whole path, since
  # other builds on the machine may be running this very test at the same time.
  pgrep -f -- "$(cd "$dir" && pwd)/$(basename "$output")\.tmp-" && { echo "FAIL: ffmpeg still running"; exit 1; }
  echo "ok: no video, no temporary file"
fi
exit 0
