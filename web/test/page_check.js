// node page_check.js URL NATIVE.png [SCREENSHOT.png]: opens the playground in
// Debian's chromium (puppeteer-core), waits for its first picture, and checks
// that the page logged no error and that the canvas holds `f2 render`'s bytes
// of the default scene's frame 0 at the canvas size (docs/web.md).
'use strict';
const fs = require('fs');
const puppeteer = require('puppeteer-core');
const {readPng} = require('./png');

async function main() {
  const [url, pngPath, screenshot] = process.argv.slice(2);
  const native = readPng(fs.readFileSync(pngPath));
  const browser = await puppeteer.launch({
    executablePath: process.env.F2_CHROMIUM || '/usr/bin/chromium',
    args: ['--no-sandbox', '--headless=new'],
  });
  const problems = [];
  try {
    const page = await browser.newPage();
    await page.setViewport({width: 1400, height: 650});
    page.on('console', (m) => {
      if (m.type() === 'error') problems.push(`console error: ${m.text()}`);
    });
    page.on('pageerror', (e) => problems.push(`uncaught: ${e.message}`));
    await page.goto(url);
    await page.waitForFunction(() => window.f2Page && window.f2Page.renders > 0, {timeout: 60000});
    const result = await page.evaluate(() => {
      const canvas = document.getElementById('picture');
      const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
      return {width: canvas.width, height: canvas.height, pixels: Array.from(data),
              build: document.getElementById('build').textContent, ms: window.f2Page.lastRender.ms};
    });
    if (screenshot) await page.screenshot({path: screenshot});
    if (result.width !== native.width || result.height !== native.height)
      throw new Error(`canvas ${result.width}x${result.height}, f2 render ${native.width}x${native.height}`);
    let differing = 0, largest = 0;
    for (let p = 0; p < result.width * result.height; ++p) {
      let d = 0;
      for (let k = 0; k < 4; ++k) d = Math.max(d, Math.abs(result.pixels[p * 4 + k] - native.rgba[p * 4 + k]));
      if (d > 0) ++differing;
      largest = Math.max(largest, d);
    }
    console.log(`${url}: ${result.build}; first picture in ${result.ms.toFixed(0)} ms; ` +
                `${differing} of ${result.width * result.height} pixels differ from f2 render, by at most ${largest}`);
    if (differing > 0) problems.push('the canvas differs from f2 render');
  } finally {
    await browser.close();
  }
  for (const p of problems) console.log(`FAIL: ${p}`);
  if (problems.length) process.exitCode = 1;
}

main().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
