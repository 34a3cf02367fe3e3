#!/usr/bin/env bash
# The whole test suite under the sanitizer presets (asan, tsan): see check-presets.sh.
exec "$(dirname "$0")/check-presets.sh" asan tsan
