#!/usr/bin/env bash
# Builds and runs the whole test suite in other CMake presets, for CI: under
# AddressSanitizer + UBSan (asan), ThreadSanitizer (tsan), and with the other
# SIMD widths — AVX2's 8 lanes (avx2) and the scalar fallback (portable) —
# since `-march=native` here picks AVX-512. The width presets build and run
# only what the lanes change (the core's unit, packet and render tests; their
# `targets` and `filter` in CMakePresets.json); the rest does not depend on
# the lanes, and the release suite runs it. Exit status non-zero if any
# fails. Timings of each step are printed at the end.
#
#   scripts/check-presets.sh [PRESET...]   (default: asan tsan portable avx2)
#   scripts/sanitize.sh                    (asan tsan)
#
# Environment:
#   F2_SANITIZE_EXCLUDE  ctest -E regex of tests to leave out, instead of the
#                        test preset's own `filter` (CMakePresets.json: asan
#                        and tsan leave out what measures speed or memory);
#                        then every target is built, not the preset's `targets`
#   F2_SANITIZE_JOBS     parallel build and test jobs (default 2)
set -uo pipefail
cd "$(dirname "$0")/.."
presets=("$@")
[ ${#presets[@]} -eq 0 ] && presets=(asan tsan portable avx2)
jobs=${F2_SANITIZE_JOBS:-2}
exclude=${F2_SANITIZE_EXCLUDE:-}

# Sanitizer behaviour: stop at the first report, keep stacks readable.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}

status=0
summary=()
now() { date +%s; }
for preset in "${presets[@]}"; do
  t0=$(now)
  if ! cmake --preset "$preset" >/dev/null; then
    summary+=("$preset: configure FAILED"); status=1; continue
  fi
  # A preset's `targets` are those its own filter's tests need; another
  # filter may need them all.
  build=(--preset "$preset" -j "$jobs")
  [ -n "$exclude" ] && build+=(--target all)
  if ! cmake --build "${build[@]}"; then
    summary+=("$preset: build FAILED"); status=1; continue
  fi
  t1=$(now)
  # Label `once`: checks of sources and scripts that run none of the preset's
  # code; the release suite (scripts/test.sh) runs them.
  args=(--preset "$preset" -j "$jobs" --timeout 600 -LE '^once$')
  [ -n "$exclude" ] && args+=(-E "$exclude")
  log=build/$preset/preset-ctest.log
  ctest "${args[@]}" 2>&1 | tee "$log" | grep -E "tests passed|FAILED|Failed|\*\*\*" || true
  result=$(grep -E "tests passed" "$log" || echo "no result")
  t2=$(now)
  if ! grep -q "100% tests passed" "$log"; then status=1; fi
  summary+=("$preset: build $((t1 - t0)) s, tests $((t2 - t1)) s: $result")
done
echo
echo "== presets =="
printf '%s\n' "${summary[@]}"
exit $status
