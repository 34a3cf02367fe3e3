#!/usr/bin/env bash
# language_files_check.sh F2 SOURCE_DIR OUT: the committed TextMate grammar and
# fuzz dictionary are what the language table generates from their templates
# (scripts/generate-language-files.sh), so no command or mode is missing there.
set -eu
f2=$1 src=$2 out=$3
mkdir -p "$out"
status=0
check() {
  local template=$1 committed=$2
  "$f2" language --fill "$src/$template" > "$out/$(basename "$committed")"
  if ! cmp -s "$out/$(basename "$committed")" "$src/$committed"; then
    echo "FAIL: $committed differs from what the language table generates from $template:"
    diff "$src/$committed" "$out/$(basename "$committed")" | head -20
    echo "(run scripts/generate-language-files.sh and commit the result)"
    status=1
  fi
}
check editors/textmate/f2.tmLanguage.template.json editors/textmate/f2.tmLanguage.json
check fuzz/f2.dict.in fuzz/f2.dict
[ $status = 0 ] && echo "OK: the grammar and the fuzz dictionary follow the language table"
exit $status
