#!/usr/bin/env bash
# Installs what is missing (everything, see install-deps.sh, and the npm
# packages of the Node.js tests, install-node-packages.sh), builds (Release)
# with the tests and benchmarks, and runs every test with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/install-node-packages.sh
# Explicitly on: run.sh may have configured build/release without them.
cmake --preset release -DF2_BUILD_TESTS=ON -DF2_BUILD_BENCH=ON
cmake --build --preset release
ctest --preset release "$@"
