#!/usr/bin/env bash
# node_test.sh SCRIPT [--needs-packages]: runs a Node.js test of the VS Code
# extension (editors/vscode/SCRIPT). With --needs-packages it needs the npm
# packages that `npm ci` in editors/vscode installs (the grammar test does).
# Skipped (tests/skip.sh: skip_missing) when Node.js or those packages are missing.
set -u
. "$(dirname "$0")/../skip.sh"
ext=$(cd "$(dirname "$0")/../../editors/vscode" && pwd)
script=$1
if ! command -v node >/dev/null 2>&1; then
  skip_missing "node is not installed (scripts/install-deps.sh installs nodejs and npm)"
fi
if [ "${2:-}" = --needs-packages ] &&
   { [ ! -d "$ext/node_modules/vscode-textmate" ] || [ ! -d "$ext/node_modules/vscode-oniguruma" ]; }; then
  skip_missing "$script needs its npm packages: run 'npm ci' in editors/vscode (scripts/test.sh does)"
fi
cd "$ext" && exec node "$script"
