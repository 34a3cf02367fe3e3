#!/usr/bin/env bash
# node_engines_check.sh SOURCE_DIR WORK_DIR: scripts/check-node-engines.js
# fails on a lock with a package that needs node >= 20, naming the package, its
# version and its range; passes on one whose packages all allow 18.20; and
# passes on the repository's own locks (issue 31: Debian 12's node is 18.20).
set -uo pipefail
src=$1 work=$2
. "$src/tests/skip.sh"
command -v node >/dev/null 2>&1 || skip_missing "node is not installed (scripts/install-deps.sh installs nodejs and npm)"
check=$src/scripts/check-node-engines.js
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

# A lock as npm 7+ writes it: the root, a nested package and two top ones.
cat > "$work/new.json" <<'JSON'
{ "name": "demo", "lockfileVersion": 3, "packages": {
  "": { "name": "demo", "engines": { "node": ">=16" } },
  "node_modules/old-enough": { "version": "1.0.0", "engines": { "node": ">=14" } },
  "node_modules/a/node_modules/undici": { "version": "7.30.2", "engines": { "node": ">= 20" } },
  "node_modules/no-engines": { "version": "2.0.0" } } }
JSON
out=$("$check" "$work/new.json" 2>&1) && fail "a '>= 20' package passed: $out"
echo "$out"
grep -q 'a > undici@7.30.2 requires node ">= 20", which excludes 18.20.4' <<<"$out" ||
  fail "the message does not name the package, its version and its range"
[ "$(grep -c 'requires node' <<<"$out")" -eq 1 ] || fail "a package that allows 18.20 was reported"

# The same lock without it passes; a range that 18.20 satisfies only as an alternative too.
sed -e 's/">= 20"/"^18.19.0 || >=20"/' "$work/new.json" > "$work/ok.json"
"$check" "$work/ok.json" || fail "a lock whose packages allow 18.20.4 failed"
# The floor can be moved, for the day Debian's node changes.
"$check" --node 20.0.0 "$work/new.json" || fail "--node 20.0.0 still rejected '>= 20'"
# npm 6's lock records no engines: it cannot be checked, so it is refused.
echo '{ "lockfileVersion": 1, "dependencies": {} }' > "$work/v1.json"
out=$("$check" "$work/v1.json" 2>&1) && fail "a version-1 lock passed"
grep -q 'has no "packages"' <<<"$out" || fail "a version-1 lock was not refused: $out"

# Every lock file the repository holds.
(cd "$src" && "$check") || fail "a committed package-lock.json needs a newer node than Debian 12's"
echo "ok"
