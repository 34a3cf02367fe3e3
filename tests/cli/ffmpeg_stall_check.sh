#!/usr/bin/env bash
# ffmpeg_stall_check.sh SIGNAL STOP FAKEBIN DIR F2 ARGS...: f2 renders a video
# (`F2 ARGS... -o DIR/v.mp4`) into the fake ffmpeg of FAKEBIN, which never
# reads (and with STOP=1 stops itself). Once its input pipe is full, so that f2
# is certainly blocked writing a frame, SIGNAL goes to f2, which must exit with
# 128 + SIGNAL, having killed and reaped ffmpeg and removed its temporary file.
# No sleeps to hope for an order of events: each step waits for a condition
# (bounded, so a regression fails instead of hanging).
set -u
sig=$1 stop=$2 fakebin=$3 dir=$4
shift 4
rm -rf "$dir" && mkdir -p "$dir"
export F2_FAKE_FFMPEG=stall F2_FAKE_FFMPEG_PIDFILE=$dir/ffmpeg.pid F2_FAKE_FFMPEG_READY=$dir/ready
[ "$stop" = 1 ] && export F2_FAKE_FFMPEG_STOP=1
PATH="$fakebin:$PATH" "$@" -o "$dir/v.mp4" 2>"$dir/stderr.txt" &
pid=$!

# wait_for CONDITION...: polls until it holds; false after 30 s (a hang, not a slow machine).
wait_for() {
  local end=$((SECONDS + 30))
  while ((SECONDS < end)); do "$@" && return 0; sleep 0.01; done
  return 1
}
wait_for test -e "$dir/ready" || { echo "FAIL: the fake ffmpeg's pipe never filled"; kill -9 $pid; exit 1; }
ffmpeg_pid=$(cat "$dir/ffmpeg.pid")
if [ "$stop" = 1 ]; then
  wait_for sh -c "grep -q '^State:.*stopped' /proc/$ffmpeg_pid/status" || { echo "FAIL: ffmpeg did not stop"; exit 1; }
fi
kill -s "$sig" $pid
if ! wait_for sh -c "! kill -0 $pid 2>/dev/null || grep -q '^State:.*zombie' /proc/$pid/status"; then
  echo "FAIL: f2 still runs 30 s after SIG$sig"; kill -9 $pid "$ffmpeg_pid"; exit 1
fi
wait $pid
code=$?
cat "$dir/stderr.txt"
want=$((128 + $(kill -l "$sig")))
[ "$code" -eq "$want" ] || { echo "FAIL: exit $code, expected $want"; exit 1; }
grep -q "interrupted" "$dir/stderr.txt" || { echo "FAIL: no 'interrupted' message"; exit 1; }
if kill -0 "$ffmpeg_pid" 2>/dev/null; then echo "FAIL: ffmpeg ($ffmpeg_pid) left running"; kill -9 "$ffmpeg_pid"; exit 1; fi
left=$(ls -A "$dir" | grep -v -e '^stderr.txt$' -e '^ffmpeg.pid$' -e '^ready$')
[ -z "$left" ] || { echo "FAIL: left in $dir: $left"; exit 1; }
echo "ok: SIG$sig stopped f2 while ffmpeg did not read; ffmpeg reaped, nothing left"
