#!/usr/bin/env bash
# Installs what is missing (everything, see install-deps.sh), builds (Release)
# with the tests and benchmarks, and runs every test with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# The npm packages of the VS Code extension's tests (lsp.textmate_grammar,
# lsp.vscode_extension), once; offline they are skipped with a reason.
if [ ! -d editors/vscode/node_modules ] && command -v npm >/dev/null; then
  (cd editors/vscode && npm ci --no-audit --no-fund --loglevel=error) || echo "test: npm ci failed; the Node tests will be skipped"
fi
# Explicitly on: run.sh may have configured build/release without them.
cmake --preset release -DF2_BUILD_TESTS=ON -DF2_BUILD_BENCH=ON
cmake --build --preset release
ctest --preset release "$@"
