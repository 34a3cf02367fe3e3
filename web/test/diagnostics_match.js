// node diagnostics_match.js MODULE.js F2 DRIVES.f2: for scenes with errors
// and warnings, the module's diagnostics (f2_set_scene) are `f2 check`'s —
// line, column, severity and message, in order — and each marks a range of
// its line; a scene with an error leaves the last good scene (docs/web.md).
'use strict';
const childProcess = require('child_process');
const fs = require('fs');
const path = require('path');
const {wrapF2Module} = require('../src/f2_module');

function checkLines(f2Path, text) {
  const run = childProcess.spawnSync(f2Path, ['check', '-'], {input: text, encoding: 'utf8'});
  return run.stderr.split('\n').filter((l) => l.startsWith('<stdin>:')).map((l) => l.slice('<stdin>:'.length));
}

async function main() {
  const [modulePath, f2Path, drivesPath] = process.argv.slice(2);
  const f2 = wrapF2Module(await require(path.resolve(modulePath))());
  const drives = fs.readFileSync(drivesPath, 'utf8');
  const cases = {
    'wrong argument count': '/sphere s1 50 0 0 0\n/sphere s2 1 2\n',
    'unknown key target': '/box b 10 10 10 0 0 0\n/key 1s nosuch 0 0 0 0 0 0\n',
    'several errors, a tab and a quote': '/box b 10 10 10 0 0 0\n\t/paint b 1 2\n/caption 0 1 0.1 0.1 0.1 "open\n/nosuch 1\n',
    'non-ASCII before the error': '# é\n/box b 10 10 10 0 0 0 # ü\n/paint b 1 x 3\n',
    'a warning only': '# nothing but a comment\n',
    'a drive without a finite value': drives.replace('(40 * sin(frame / 6))', '(40 / (frame - 12))'),
  };
  let failures = 0;
  const good = f2.setScene('/sphere s 50 0 0 0\n');
  if (!good.ok) throw new Error(`a good scene has errors: ${JSON.stringify(good)}`);
  for (const [name, text] of Object.entries(cases)) {
    const expected = checkLines(f2Path, text);
    const result = f2.setScene(text);
    const ours = result.diagnostics.map((d) => `${d.line}:${d.column}: ${d.severity}: ${d.message}`);
    const lines = text.split('\n');
    const badRanges = result.diagnostics.filter((d) => {
      const lineBytes = Buffer.byteLength(lines[d.line - 1] || '');
      return !(d.markColumn >= 1 && d.endColumn > d.markColumn && d.endColumn <= lineBytes + 1);
    });
    const same = JSON.stringify(ours) === JSON.stringify(expected);
    const hasError = expected.some((l) => l.includes(': error: '));
    console.log(`${same && !badRanges.length && result.ok === !hasError ? 'ok  ' : 'FAIL'} ${name}: ` +
                `${ours.length} diagnostic(s), first: ${ours[0] || '-'}`);
    if (!same) {
      console.log(`  f2 check: ${JSON.stringify(expected)}\n  module:   ${JSON.stringify(ours)}`);
      ++failures;
    }
    if (badRanges.length) {
      console.log(`  marked ranges outside their line: ${JSON.stringify(badRanges)}`);
      ++failures;
    }
    if (result.ok === hasError) {
      console.log(`  ok is ${result.ok} with ${hasError ? 'an error' : 'no error'}`);
      ++failures;
    }
  }
  // The good scene is still the one rendered after the errors.
  if (!f2.render(0, 8, 6, 0, 6)) {
    console.log('FAIL: no picture after scenes with errors');
    ++failures;
  }
  if (failures) process.exitCode = 1;
}

main().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
