#!/usr/bin/env sh
# Packages the extension as f2-stage-VERSION.vsix with @vscode/vsce, a dev
# dependency that `npm ci` installs (packaging itself needs no network):
#   editors/vscode/scripts/package.sh
# Install it with: code --install-extension f2-stage-0.1.0.vsix
set -eu
cd "$(dirname "$0")/.."
npm ci --omit=optional --no-audit --no-fund
npx --no-install vsce package --skip-license --allow-missing-repository "$@"
