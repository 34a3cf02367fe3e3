#!/usr/bin/env bash
# spec_anchors_check.sh SOURCE_DIR: every "SPEC n" or "SPEC n.m" cited in the
# code, the tests or the docs has its anchor (id="spec-n-m") in
# docs/scene-language.md, each anchor is there once, and the check itself
# fails on a citation without an anchor (issue 23: citations that lead somewhere).
set -uo pipefail
src=$1
doc=$src/docs/scene-language.md
fail() { echo "FAIL: $*"; exit 1; }

# The sections cited as n or n.m, one per line ("10.7" -> "spec-10-7").
cited() { grep -rhoE 'SPEC [0-9]+(\.[0-9]+)?' "$@" | sed -E 's/SPEC /spec-/; s/\./-/' | sort -u; }
anchors() { grep -oE 'id="spec-[0-9]+(-[0-9]+)?"' "$1" | sed -E 's/id="(.*)"/\1/'; }

dupes=$(anchors "$doc" | sort | uniq -d)
[ -z "$dupes" ] || fail "anchors given twice in docs/scene-language.md: $dupes"
missing=$(comm -23 <(cited "$src/src" "$src/apps" "$src/tests/unit" "$src/tests/lsp" "$src/docs") <(anchors "$doc" | sort -u))
[ -z "$missing" ] || fail "cited without an anchor in docs/scene-language.md: $(echo $missing)"

# The check sees a citation that has no anchor.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo '// as SPEC 99.9 says' > "$tmp/x.cpp"
[ -n "$(comm -23 <(cited "$tmp") <(anchors "$doc" | sort -u))" ] || fail "a citation of SPEC 99.9 went unnoticed"
echo "every cited SPEC section has its anchor ($(anchors "$doc" | wc -l) anchors)"
