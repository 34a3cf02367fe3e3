#!/usr/bin/env sh
# Packages the extension as f2-stage-VERSION.vsix (with @vscode/vsce from npm):
#   editors/vscode/scripts/package.sh
# Install it with: code --install-extension f2-stage-0.1.0.vsix
set -eu
cd "$(dirname "$0")/.."
npm ci --no-audit --no-fund
npx --yes @vscode/vsce package --skip-license --allow-missing-repository "$@"
