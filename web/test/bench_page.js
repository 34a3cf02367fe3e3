// node bench_page.js URL FRAMES KEYS: one run of the page's speed benchmark
// (scripts/web-bench.sh) in headless chromium; prints one JSON line:
//  - fps: frames per second while playing, 1000 / the median interval
//    between pictures reaching the canvas (FRAMES frames after the first),
//    as `f2 bench` counts; fpsMean: over the whole run; workerMs: the median
//    frame's render time summed over its chunks and divided by the workers
//    (what each worker computed), overheadMs: the rest of a frame's interval;
//  - latency: from a keystroke (a digit of /background typed over) to the
//    quarter-resolution picture and to the full one on the canvas, KEYS
//    times with the page idle, and KEYS times typed while the anti-aliased
//    picture is being rendered (medians).
'use strict';
const puppeteer = require('puppeteer-core');

const median = (values) => {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted.length ? sorted[Math.floor((sorted.length - 1) / 2)] : NaN;
};

async function main() {
  const [url, frameCount, keyCount] = [process.argv[2], Number(process.argv[3] || 48), Number(process.argv[4] || 7)];
  const browser = await puppeteer.launch({
    executablePath: process.env.F2_CHROMIUM || '/usr/bin/chromium',
    args: ['--no-sandbox', '--headless=new'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({width: 1600, height: 900});
    page.on('pageerror', (e) => console.error(`uncaught: ${e.message}`));
    await page.evaluateOnNewDocument(() => {
      window.pictures = [];
      window.addEventListener('f2picture', (event) => {
        const r = window.f2Page.lastRender;
        window.pictures.push({...event.detail, at: performance.now(), bandMs: r.bandMs});
      });
      document.addEventListener('keydown', () => {
        window.keyAt = performance.now();
      }, true);
    });
    await page.goto(url);
    const settled = () => page.waitForFunction(() => window.f2Page && window.f2Page.settled && window.f2Page.editor,
                                               {timeout: 120000});
    await settled();
    const info = await page.evaluate(() => ({build: document.getElementById('build').textContent,
                                             width: document.getElementById('picture').width,
                                             height: document.getElementById('picture').height,
                                             workers: window.f2Page.workers.length}));

    // Playing from frame 0.
    const start = await page.evaluate(() => window.pictures.length);
    await page.click('#play');
    await page.waitForFunction((n, frames) => window.pictures.length >= n + frames + 1, {timeout: 600000}, start,
                               frameCount);
    await page.click('#play');
    const played = (await page.evaluate(() => window.pictures)).slice(start, start + frameCount + 1);
    const intervals = played.slice(1).map((p, i) => p.at - played[i].at);
    const workerMs = played.slice(1).map((p) => p.bandMs.reduce((a, b) => a + b, 0) / info.workers);
    // As f2 bench: 1000 / the median frame time; and the mean over the run, stalls included.
    const fps = 1000 / median(intervals);
    const fpsMean = frameCount * 1000 / (played[played.length - 1].at - played[0].at);

    // Keystrokes: a digit of /background typed over, 6 and 7 in turn.
    const position = await page.evaluate(() => {
      const text = window.f2Page.editor.text();
      const line = text.split('\n').findIndex((l) => l.startsWith('/background'));
      const view = window.f2Page.editor.view;
      return view.state.doc.line(line + 1).to - 1;  // the last digit
    });
    const latencies = {idle: [], idleFull: [], duringAa: [], duringAaFull: []};
    for (let k = 0; k < 2 * keyCount; ++k) {
      const duringAa = k % 2 === 1;
      await settled();
      if (duringAa) {
        // Wait for the full picture; the anti-aliased one is then in flight.
        const n = await page.evaluate(() => window.f2Page.renders);
        await page.click('#resetView');  // renders the same picture again: quarter, full, anti-aliased
        await page.waitForFunction((m) => window.f2Page.renders >= m + 2 && !window.f2Page.settled, {timeout: 60000}, n);
      }
      await page.evaluate((at) => {
        const view = window.f2Page.editor.view;
        view.focus();
        view.dispatch({selection: {anchor: at, head: at + 1}});
      }, position);
      const before = await page.evaluate(() => window.pictures.length);
      await page.keyboard.type(k % 4 < 2 ? '7' : '6');
      await page.waitForFunction((n) => window.pictures.slice(n).some((p) => p.scale === 1 && p.at > window.keyAt),
                                 {timeout: 60000}, before);
      const after = await page.evaluate((n) => ({key: window.keyAt, pictures: window.pictures.slice(n)}), before);
      const preview = after.pictures.find((p) => p.scale !== 1 && p.at > after.key);
      const full = after.pictures.find((p) => p.scale === 1 && p.at > after.key);
      latencies[duringAa ? 'duringAa' : 'idle'].push(preview ? preview.at - after.key : NaN);
      latencies[duringAa ? 'duringAaFull' : 'idleFull'].push(full.at - after.key);
    }
    console.log(JSON.stringify({
      ...info, frames: frameCount, fps, fpsMean, msMedian: median(intervals), workerMs: median(workerMs),
      overheadMs: median(intervals) - median(workerMs), chunks: played[1].bandMs.length,
      latencyMs: median(latencies.idle), latencyFullMs: median(latencies.idleFull),
      latencyDuringAaMs: median(latencies.duringAa), latencyDuringAaFullMs: median(latencies.duringAaFull),
    }));
  } finally {
    await browser.close();
  }
}

main().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
