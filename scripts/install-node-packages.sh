#!/usr/bin/env bash
# Installs the npm packages of the repository's Node.js tool chains from their
# committed lock files (`npm ci`), again whenever a lock file changed:
# editors/vscode (the VS Code extension's tests and packaging) and tests/gltf
# (the Khronos glTF validator and three.js, which check `f2 export --gltf`),
# web (CodeMirror and esbuild: the web page's editor) and web/test
# (puppeteer-core, which drives chromium against the web page).
#
# Offline it says so and exits 0: the Node tests are then skipped with their
# reason. Under F2_REQUIRE_ALL_TESTS=1 (.ci/run), where the registry is
# reachable, a failed install is an error (exit 1).
set -uo pipefail
cd "$(dirname "$0")/.."
dirs=(editors/vscode tests/gltf web web/test)

status=0
for dir in "${dirs[@]}"; do
  stamp=$dir/node_modules/.f2-lock
  [ -f "$stamp" ] && cmp -s "$dir/package-lock.json" "$stamp" && continue
  # --omit=optional in editors/vscode: keytar (vsce's store of publishing
  # tokens) would try to download a native build; packaging does not use it.
  # Not in web: esbuild's binary is an optional package.
  omit=()
  [ "$dir" = editors/vscode ] && omit=(--omit=optional)
  if command -v npm >/dev/null &&
     (cd "$dir" && npm ci "${omit[@]}" --no-audit --no-fund --loglevel=error); then
    cp "$dir/package-lock.json" "$stamp"
  else
    echo "install-node-packages: npm ci in $dir failed; its Node tests will be skipped" >&2
    status=1
  fi
done
if [ $status -ne 0 ] && [ "${F2_REQUIRE_ALL_TESTS:-}" = 1 ]; then
  echo "install-node-packages: F2_REQUIRE_ALL_TESTS=1: the Node tests may not be skipped" >&2
  exit 1
fi
exit 0
