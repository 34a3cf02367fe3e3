// node render_matches_native.js MODULE.js SCENE.f2 NATIVE.png FRAME: the
// module renders the scene's frame at the PNG's size, in uneven bands of rows
// as the page's workers do, and must give `f2 render`'s bytes (docs/web.md).
'use strict';
const fs = require('fs');
const path = require('path');
const {readPng} = require('./png');
const {wrapF2Module} = require('../src/f2_module');

async function main() {
  const [modulePath, scenePath, pngPath, frameText] = process.argv.slice(2);
  const createF2Module = require(path.resolve(modulePath));
  const f2 = wrapF2Module(await createF2Module());
  const native = readPng(fs.readFileSync(pngPath));
  const {width, height} = native;
  const scene = f2.setScene(fs.readFileSync(scenePath, 'utf8'));
  if (!scene.ok) throw new Error(`the scene has errors: ${JSON.stringify(scene.diagnostics)}`);

  // Bands that are not whole tiles, so a band boundary splits a 32-row tile.
  const cuts = [0, Math.floor(height / 3), Math.floor(height / 3) + 7, height];
  const ours = new Uint8ClampedArray(width * height * 4);
  for (let i = 0; i + 1 < cuts.length; ++i) {
    const band = f2.render(Number(frameText), width, height, cuts[i], cuts[i + 1]);
    if (!band) throw new Error(`no image for rows ${cuts[i]}..${cuts[i + 1]}`);
    ours.set(band, cuts[i] * width * 4);
  }

  let differing = 0, largest = 0;
  for (let p = 0; p < width * height; ++p) {
    let d = 0;
    for (let k = 0; k < 4; ++k) d = Math.max(d, Math.abs(ours[p * 4 + k] - native.rgba[p * 4 + k]));
    if (d > 0) ++differing;
    largest = Math.max(largest, d);
  }
  console.log(`${f2.buildName()} build, ${path.basename(scenePath)} frame ${frameText} at ${width}x${height}: ` +
              `${differing} of ${width * height} pixels differ from f2 render, by at most ${largest}`);
  if (differing > 0) {
    process.exitCode = 1;
  }
  // Requests the module cannot honour give no picture rather than a wrong one.
  for (const [frame, y0, y1] of [[NaN, 0, 1], [Infinity, 0, 1], [0, 0, height + 1], [0, 5, 5], [0, -1, 3]]) {
    if (f2.render(frame, width, height, y0, y1) !== null) {
      console.log(`FAIL: a picture for frame ${frame}, rows ${y0}..${y1}`);
      process.exitCode = 1;
    }
  }
}

main().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
