#!/usr/bin/env bash
# Checks that the repository stands alone: no file points at something a user
# who clones it does not have — the team's folder beside the checkout, the
# machine it was written on (its work folder, a home directory), or the
# specification and style notes kept outside it (SPEC.md, STYLE.md; the
# specification is stated in docs/rendering.md and docs/scene-language.md and
# cited as "SPEC n").
# Exit 1 with one line per finding; 0 when the tree is clean.
#
# Usage: scripts/check-standalone.sh
set -euo pipefail
cd "$(dirname "$0")/.."
self=scripts/check-standalone.sh

# What may not appear (extended regular expressions; written so that this
# file does not match them itself).
patterns=(
  '[.][.]/sha[r]ed'
  '(^|[^[:alnum:]_.~-])/work(/|$)'
  '(^|[^[:alnum:]_.~-])/home/[[:alnum:]_]'
  '(^|[^[:alnum:]_.~-])/root/'
  '\bSPEC\.md\b'
  '\bSTYLE\.md\b'
)
args=()
for p in "${patterns[@]}"; do args+=(-e "$p"); done

# Tracked text files when this is a git checkout, else every file but builds.
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  found=$(git grep -n -I -E "${args[@]}" -- . ":!$self" || true)
else
  found=$(grep -rn -I -E "${args[@]}" --exclude-dir=build --exclude-dir=.git . | sed 's|^\./||' |
    grep -v "^$self:" || true)
fi
if [[ -n "$found" ]]; then
  sed 's/^/check-standalone: /' <<< "$found"
  echo "check-standalone: $(wc -l <<< "$found") reference(s) to something outside the repository"
  exit 1
fi
echo "check-standalone: ok (no path outside the repository)"
