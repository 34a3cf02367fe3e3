#!/usr/bin/env node
// Fails when any package locked in a package-lock.json declares an
// `engines.node` range that leaves out the node a user's Debian 12 has
// (18.20.4), naming the lock, the package, its version and its range. The
// machines CI runs on may have a newer node first on the PATH, so a green
// run alone does not prove that a fresh Debian can run our npm tool chains.
//
//   scripts/check-node-engines.js [--node VERSION] [LOCK...]
//
// Without LOCK it checks every package-lock.json git tracks in this
// repository. Range matching is npm's own (the semver package npm ships).
'use strict';
const { execFileSync } = require('child_process');
const fs = require('fs');
const path = require('path');

const kDebianNode = '18.20.4';  // Debian 12's nodejs 18.20.4+dfsg-1~deb12u1

/// npm's semver: Debian's node finds it in /usr/share/nodejs; another node
/// finds the copy inside its own npm.
function loadSemver() {
  const places = ['semver', '/usr/share/nodejs/semver'];
  try {
    const root = execFileSync('npm', ['root', '-g'], { encoding: 'utf8' }).trim();
    places.push(path.join(root, 'npm', 'node_modules', 'semver'));
  } catch (_) { /* no npm on the PATH: only the first two places */ }
  for (const place of places) {
    try { return require(place); } catch (_) { /* the next place */ }
  }
  console.error('check-node-engines: cannot find the semver package (install Debian\'s npm)');
  process.exit(2);
}

function usage() {
  console.error('usage: check-node-engines.js [--node VERSION] [LOCK...]');
  process.exit(2);
}

const args = process.argv.slice(2);
let node = kDebianNode;
const locks = [];
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--node') {
    if (i + 1 >= args.length) usage();
    node = args[++i];
  } else if (args[i].startsWith('-')) {
    usage();
  } else {
    locks.push(args[i]);
  }
}
if (locks.length === 0) {
  const top = execFileSync('git', ['rev-parse', '--show-toplevel'], { encoding: 'utf8' }).trim();
  const tracked = execFileSync('git', ['-C', top, 'ls-files', '*package-lock.json'], { encoding: 'utf8' });
  for (const f of tracked.split('\n').filter(Boolean)) locks.push(path.join(top, f));
}

const semver = loadSemver();
if (!semver.valid(node)) {
  console.error(`check-node-engines: '${node}' is not a version`);
  process.exit(2);
}

const failures = [];
let checked = 0;
for (const lockPath of locks) {
  let lock;
  try {
    lock = JSON.parse(fs.readFileSync(lockPath, 'utf8'));
  } catch (e) {
    failures.push(`${lockPath}: cannot read it as JSON (${e.message})`);
    continue;
  }
  // Lock files of npm 7 and later list every package with its engines;
  // version 1 (npm 6) does not record them, so it cannot be checked.
  if (!lock.packages) {
    failures.push(`${lockPath}: lockfileVersion ${lock.lockfileVersion} has no "packages" ` +
                  '(regenerate it with npm 7 or later)');
    continue;
  }
  for (const [where, pkg] of Object.entries(lock.packages)) {
    ++checked;
    const range = pkg.engines && (Array.isArray(pkg.engines) ? null : pkg.engines.node);
    if (typeof range !== 'string') continue;
    if (semver.satisfies(node, range, { includePrerelease: true })) continue;
    // "node_modules/a/node_modules/b" is "a > b": b as a dependency of a.
    const name = where === '' ? (lock.name || '(the project)')
                              : where.replace(/^node_modules\//, '').split('/node_modules/').join(' > ');
    failures.push(`${lockPath}: ${name}@${pkg.version || '?'} requires node "${range}", ` +
                  `which excludes ${node}`);
  }
}

for (const f of failures) console.error('check-node-engines: ' + f);
if (failures.length > 0) {
  console.error(`check-node-engines: ${failures.length} locked package(s) cannot run on node ${node}`);
  process.exit(1);
}
console.log(`check-node-engines: ${checked} locked packages in ${locks.length} lock file(s) allow node ${node}`);
