#!/usr/bin/env bash
# stdin_interrupt_check.sh F2 DIR: Ctrl+C (SIGINT) while `f2 render -` waits
# for its scene on standard input ends f2 with status 130, as for any program
# killed by Ctrl+C, and writes nothing.
# Deterministic: the signal is sent once f2 itself (not the shell starting it)
# sleeps reading the FIFO that stands in for the terminal.
. "$(dirname "$0")/../skip.sh"
set -u -m  # job control: a background job would otherwise ignore SIGINT
f2=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir"
fifo="$dir/scene.fifo"
mkfifo "$fifo"
"$f2" render - -o "$dir/never.png" <"$fifo" 2>"$dir/stderr.txt" &
pid=$!
exec 3>"$fifo"  # returns once f2's side is open too
reading=0
for ((i = 0; i < 1500; ++i)); do  # a bound only for kernels without wchan: then skipped
  if [ "$(readlink "/proc/$pid/exe")" = "$(readlink -f "$f2")" ] &&
    grep -q pipe "/proc/$pid/wchan" 2>/dev/null; then reading=1; break; fi
  sleep 0.02
done
if [ "$reading" -eq 0 ]; then
  kill "$pid"; wait "$pid"
  skip_impossible "cannot see f2 waiting on the FIFO (/proc/PID/wchan)"
fi
kill -INT "$pid"
wait "$pid"
code=$?
exec 3>&-
cat "$dir/stderr.txt"
[ "$code" -eq 130 ] || { echo "FAIL: exit $code, expected 130"; exit 1; }
[ -e "$dir/never.png" ] && { echo "FAIL: an image was written"; exit 1; }
echo "ok: exit 130, nothing written"
