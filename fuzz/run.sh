#!/usr/bin/env bash
# Builds the libFuzzer targets (preset "fuzz": clang + ASan + UBSan) and fuzzes
# the scene parser and renderer for SECONDS (default 60), or with
# F2_FUZZ_TARGET=lsp the language server's message handling.
#
#   fuzz/run.sh [SECONDS] [extra libFuzzer flags...]
#
# New inputs go to build/fuzz/corpus (the seeds in fuzz/corpus are read, never
# written); crashes, leaks and hangs to build/fuzz/artifacts/. Environment:
#   F2_FUZZ_JOBS   parallel fuzzing processes (default 1; the machine is shared)
#   F2_FUZZ_NOBUILD=1  skip configure/build
#   F2_FUZZ_TARGET     scene (default) or lsp; lsp reads fuzz/corpus-lsp and
#                      writes build/fuzz/corpus-lsp
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
jobs=${F2_FUZZ_JOBS:-1}
target=${F2_FUZZ_TARGET:-scene}
case "$target" in
  scene) fuzzer=f2_scene_fuzzer dict=fuzz/f2.dict corpus=corpus seeds=(fuzz/corpus tests/data/fuzz) ;;
  lsp) fuzzer=f2_lsp_fuzzer dict=fuzz/lsp.dict corpus=corpus-lsp seeds=(fuzz/corpus-lsp) ;;
  *) echo "fuzz/run.sh: F2_FUZZ_TARGET must be scene or lsp, got '$target'" >&2; exit 2 ;;
esac

if [[ "${F2_FUZZ_NOBUILD:-0}" != 1 ]]; then
  cmake --preset fuzz >/dev/null
  cmake --build --preset fuzz
fi

out=build/fuzz
mkdir -p "$out/$corpus" "$out/artifacts"
args=(
  -max_len=4096 -timeout=5 -rss_limit_mb=2048 -malloc_limit_mb=1024
  -dict="$dict" -max_total_time="$seconds" -print_final_stats=1
  -artifact_prefix="$out/artifacts/"
)
if (( jobs > 1 )); then args+=(-jobs="$jobs" -workers="$jobs"); fi
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
exec "$out/fuzz/$fuzzer" "${args[@]}" "$@" "$out/$corpus" "${seeds[@]}"
