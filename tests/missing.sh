#!/bin/sh
# missing.sh REASON...: the stand-in CMake registers for a test whose program
# was not found when the build was configured (skip_missing in skip.sh).
. "$(dirname "$0")/skip.sh"
skip_missing "$@"
