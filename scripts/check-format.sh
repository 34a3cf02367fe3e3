#!/usr/bin/env bash
# Fails when a tracked C++ file differs from what the project's .clang-format
# makes of it. `scripts/check-format.sh --fix` rewrites them instead.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
if ! clang-format --dry-run --Werror "${files[@]}" 2> build-format.log; then
  grep -E "^[^ ]+:[0-9]+:[0-9]+: error" build-format.log | head -20
  echo "check-format: $(grep -cE '^[^ ]+:[0-9]+:[0-9]+: error' build-format.log) places differ from .clang-format; run scripts/check-format.sh --fix"
  rm -f build-format.log
  exit 1
fi
rm -f build-format.log
echo "check-format: ${#files[@]} files follow .clang-format"
