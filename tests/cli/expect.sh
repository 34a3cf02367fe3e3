#!/usr/bin/env bash
# expect.sh EXIT REGEX [STDIN_FILE|-] -- COMMAND...
# Runs COMMAND (stdin from STDIN_FILE unless '-'), then checks that it exited with
# EXIT ('!0' = any failure) and that its stdout+stderr, lines joined by spaces,
# match the extended regex REGEX.
set -u
want_exit=$1 regex=$2 input=$3
shift 3
[ "$1" = "--" ] && shift
if [ "$input" = "-" ]; then out=$("$@" 2>&1 </dev/null); else out=$("$@" 2>&1 <"$input"); fi
code=$?
echo "$out"
if [ "$want_exit" = "!0" ]; then
  [ "$code" -ne 0 ] || { echo "FAIL: exit 0, expected a failure"; exit 1; }
elif [ "$code" -ne "$want_exit" ]; then
  echo "FAIL: exit $code, expected $want_exit"; exit 1
fi
if ! tr '\n' ' ' <<<"$out" | grep -Eq -- "$regex"; then echo "FAIL: output does not match /$regex/"; exit 1; fi
echo "ok"
