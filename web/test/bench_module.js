// node --no-experimental-fetch bench_module.js MODULE.js FRAMES: the module
// alone in node, one thread, the default scene at 800x600 from frame 0 (the
// speed benchmark's "where the time goes", scripts/web-bench.sh); prints one
// JSON line: the median ms of a whole frame in one call, and of a frame in
// 32-row chunks as the page asks for it.
'use strict';
const path = require('path');
const {wrapF2Module} = require('../src/f2_module.js');

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor((values.length - 1) / 2)];

async function main() {
  const [modulePath, frameCount] = [path.resolve(process.argv[2]), Number(process.argv[3] || 24)];
  const f2 = wrapF2Module(await require(modulePath)());
  f2.setScene('');
  const width = 800, height = 600;
  const time = (chunkRows) => {
    const ms = [];
    for (let frame = 0; frame <= frameCount; ++frame) {
      const start = performance.now();
      for (let y0 = 0; y0 < height; y0 += chunkRows) f2.render(frame, width, height, y0, Math.min(height, y0 + chunkRows));
      if (frame > 0) ms.push(performance.now() - start);  // frame 0 warms up
    }
    return median(ms);
  };
  console.log(JSON.stringify({build: f2.buildName(), wholeMs: time(height), chunkedMs: time(32)}));
}

main().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
