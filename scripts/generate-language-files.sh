#!/usr/bin/env bash
# Writes the files generated from the language table (src/core/parse/language.cpp):
# the TextMate grammar (editors/textmate/f2.tmLanguage.json, which the VS Code
# extension links) and the fuzz dictionary (fuzz/f2.dict), each from its
# template with `f2 language --fill`. Run it after adding a command, a mode,
# an option or a function; the test `language.generated_files` fails until then.
#
#   scripts/generate-language-files.sh [F2]     (default: build/release/apps/cli/f2)
set -euo pipefail
cd "$(dirname "$0")/.."
f2=${1:-build/release/apps/cli/f2}
[ -x "$f2" ] || { echo "generate-language-files: no f2 at $f2 (build first: cmake --build build/release)"; exit 1; }
# Template and the file made from it, in pairs.
pairs=(editors/textmate/f2.tmLanguage.template.json editors/textmate/f2.tmLanguage.json
       fuzz/f2.dict.in fuzz/f2.dict)
for ((i = 0; i < ${#pairs[@]}; i += 2)); do
  template=${pairs[i]} out=${pairs[i + 1]}
  "$f2" language --fill "$template" > "$out.tmp"
  mv "$out.tmp" "$out"
  echo "generate-language-files: $out"
done
