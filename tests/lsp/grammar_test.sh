#!/usr/bin/env bash
# grammar_test.sh: the TextMate grammar's scope tests (editors/vscode/test),
# with the npm packages installed by `npm ci` in editors/vscode.
# Exit 77 (skipped) when Node.js or those packages are missing.
set -u
ext=$(cd "$(dirname "$0")/../../editors/vscode" && pwd)
if ! command -v node >/dev/null 2>&1; then
  echo "SKIP: node is not installed (scripts/install-deps.sh installs nodejs and npm)"
  exit 77
fi
if [ ! -d "$ext/node_modules/vscode-textmate" ] || [ ! -d "$ext/node_modules/vscode-oniguruma" ]; then
  echo "SKIP: the grammar test needs its npm packages: run 'npm ci' in editors/vscode (.ci/run does)"
  exit 77
fi
cd "$ext" && exec node test/grammar_test.js
