#!/usr/bin/env bash
# Packages the VS Code extension with the @vscode/vsce that `npm ci` installs
# in editors/vscode (a dev dependency), with the network shut off by a dead
# proxy, and checks the .vsix: the files VS Code loads are in it (the grammar
# link resolved), the language client is bundled, tests and dev packages are not.
# Skipped (tests/skip.sh: skip_missing) when Node.js, python3 or the npm packages are missing.
set -u
. "$(dirname "$0")/../skip.sh"
ext=$(cd "$(dirname "$0")/../../editors/vscode" && pwd)
if ! command -v node >/dev/null 2>&1 || ! command -v python3 >/dev/null 2>&1; then
  skip_missing "node and python3 are needed"
fi
if [ ! -x "$ext/node_modules/.bin/vsce" ]; then
  skip_missing "@vscode/vsce is not installed: run 'npm ci' in editors/vscode (scripts/test.sh does)"
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
(cd "$ext" && HTTPS_PROXY=http://127.0.0.1:9 HTTP_PROXY=http://127.0.0.1:9 npm_config_offline=true \
  node_modules/.bin/vsce package --skip-license --allow-missing-repository -o "$out/f2.vsix") || {
  echo "FAIL: vsce package failed"
  exit 1
}
exec python3 - "$out/f2.vsix" "$ext" <<'PY'
import json, os, sys, zipfile
vsix, ext = sys.argv[1], sys.argv[2]
z = zipfile.ZipFile(vsix)
names = set(z.namelist())
failures = []
for need in ["extension.vsixmanifest", "extension/package.json", "extension/extension.js",
             "extension/language-configuration.json", "extension/snippets/f2.json",
             "extension/syntaxes/f2.tmLanguage.json",
             "extension/node_modules/vscode-languageclient/package.json"]:
    if need not in names:
        failures.append("missing " + need)
for name in names:
    for banned in ["extension/test/", "extension/scripts/", "extension/node_modules/vscode-textmate/",
                   "extension/node_modules/@vscode/vsce/", "extension/node_modules/vscode-oniguruma/"]:
        if name.startswith(banned):
            failures.append("should not be packaged: " + name)
            break
grammar = os.path.join(ext, "..", "textmate", "f2.tmLanguage.json")
if "extension/syntaxes/f2.tmLanguage.json" in names:
    with open(grammar, "rb") as f:
        if z.read("extension/syntaxes/f2.tmLanguage.json") != f.read():
            failures.append("the packaged grammar is not editors/textmate/f2.tmLanguage.json")
manifest = json.loads(z.read("extension/package.json"))
if manifest["contributes"]["languages"][0]["extensions"] != [".f2"]:
    failures.append("the packaged manifest does not claim .f2 files")
if failures:
    print("\n".join(failures))
    sys.exit(1)
print("ok: %s has %d files, the client bundled, no tests or dev packages" % (os.path.basename(vsix), len(names)))
PY
