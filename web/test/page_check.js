// node page_check.js URL FRAME0.png FRAME120.png ERROR_LINE ERROR [SCREENSHOT.png]:
// opens the playground in Debian's chromium (puppeteer-core) and checks
// (docs/web.md) that
//  - the first picture is `f2 render --frame 0` of the default scene at the
//    canvas size (FRAME0.png), byte for byte;
//  - appending the line ERROR_LINE to the text lists the diagnostic ERROR
//    (`f2 check`'s LINE:COL: error: message) and keeps the picture;
//  - removing it again renders a quarter-resolution picture, then the full
//    one (FRAME0.png again), and the frame slider at 120 shows FRAME120.png;
//  - its share link opens, in another page, the same text at frame 120 with
//    FRAME120.png's pixels, its Play button advances the frames, and its
//    Examples menu loads a gallery scene;
//  - the page logged no error and threw no exception.
'use strict';
const fs = require('fs');
const puppeteer = require('puppeteer-core');
const {readPng} = require('./png');

async function main() {
  const [url, frame0Path, frame120Path, errorLine, expectedError, screenshot] = process.argv.slice(2);
  const native = readPng(fs.readFileSync(frame0Path));
  const native120 = readPng(fs.readFileSync(frame120Path));
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
    await page.waitForFunction(() => window.f2Page && window.f2Page.fullRenders > 0, {timeout: 60000});
    const canvasBytes = () => page.evaluate(() => {
      const canvas = document.getElementById('picture');
      const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
      return {width: canvas.width, height: canvas.height, pixels: Array.from(data),
              build: document.getElementById('build').textContent, ms: window.f2Page.lastRender.ms,
              renders: window.f2Page.renders, fullRenders: window.f2Page.fullRenders,
              previewMs: window.f2Page.lastPreviewMs};
    });
    const compare = (what, result, expected) => {
      if (result.width !== expected.width || result.height !== expected.height) {
        problems.push(`${what}: canvas ${result.width}x${result.height}, f2 render ${expected.width}x${expected.height}`);
        return;
      }
      let differing = 0, largest = 0;
      for (let p = 0; p < result.width * result.height; ++p) {
        let d = 0;
        for (let k = 0; k < 4; ++k) d = Math.max(d, Math.abs(result.pixels[p * 4 + k] - expected.rgba[p * 4 + k]));
        if (d > 0) ++differing;
        largest = Math.max(largest, d);
      }
      console.log(`${url}: ${what}: ${result.build}; rendered in ${result.ms.toFixed(0)} ms; ` +
                  `${differing} of ${result.width * result.height} pixels differ from f2 render, by at most ${largest}`);
      if (differing > 0) problems.push(`${what}: the canvas differs from f2 render`);
    };
    const setText = (text) => page.evaluate((t) => {
      const area = document.getElementById('scene');
      area.value = t;
      area.dispatchEvent(new Event('input'));
    }, text);

    const first = await canvasBytes();
    compare('frame 0', first, native);
    if (screenshot) await page.screenshot({path: screenshot});

    const text = await page.evaluate(() => document.getElementById('scene').value);
    await setText(`${text}${text.endsWith('\n') ? '' : '\n'}${errorLine}\n`);
    await page.waitForFunction(() => document.querySelectorAll('#diagnostics li').length > 0, {timeout: 30000});
    const shown = await page.evaluate(() => document.querySelector('#diagnostics li').textContent);
    console.log(`${url}: with '${errorLine}': ${shown}`);
    if (shown !== expectedError) problems.push(`the page shows '${shown}', f2 check '${expectedError}'`);
    const kept = await canvasBytes();
    if (kept.renders !== first.renders) problems.push('the picture was rendered again from a scene with an error');
    compare('frame 0 kept while the text has an error', kept, native);

    await setText(text);
    await page.waitForFunction((n) => window.f2Page.fullRenders > n && !document.querySelector('#diagnostics li'),
                               {timeout: 30000}, kept.fullRenders);
    const fixed = await canvasBytes();
    if (fixed.renders < kept.renders + 2) problems.push('no quarter-resolution picture before the full one');
    console.log(`${url}: the text fixed: a quarter-resolution picture in ${fixed.previewMs.toFixed(0)} ms, ` +
                `the full one in ${fixed.ms.toFixed(0)} ms (after the page's 150 ms pause for typing)`);
    compare('frame 0 again after the fix', fixed, native);
    await page.evaluate(() => {
      const slider = document.getElementById('frame');
      slider.value = '120';
      slider.dispatchEvent(new Event('input'));
    });
    await page.waitForFunction((n) => window.f2Page.fullRenders > n && window.f2Page.lastRender.frame === 120 &&
                                          window.f2Page.lastRender.scale === 1,
                               {timeout: 30000}, fixed.fullRenders);
    compare('frame 120 from the slider', await canvasBytes(), native120);

    // Share: the link opens the same text at the same frame, the same pixels.
    await page.click('#share');
    await page.waitForFunction(() => location.hash.includes('scene='), {timeout: 30000});
    const link = page.url();
    const opened = await browser.newPage();
    opened.on('console', (m) => {
      if (m.type() === 'error') problems.push(`shared page: console error: ${m.text()}`);
    });
    opened.on('pageerror', (e) => problems.push(`shared page: uncaught: ${e.message}`));
    await opened.setViewport({width: 1400, height: 650});
    await opened.goto(link);
    await opened.waitForFunction(() => window.f2Page && window.f2Page.fullRenders > 0, {timeout: 60000});
    const shared = await opened.evaluate(() => ({text: document.getElementById('scene').value,
                                                 slider: document.getElementById('frame').value}));
    console.log(`${url}: a share link of ${link.length} characters opens frame ${shared.slider}`);
    if (shared.text !== text) problems.push('the share link opened another text');
    if (shared.slider !== '120') problems.push(`the share link opened frame ${shared.slider}, not 120`);
    const sharedPicture = await opened.evaluate(() => {
      const canvas = document.getElementById('picture');
      const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
      return {width: canvas.width, height: canvas.height, pixels: Array.from(data),
              build: document.getElementById('build').textContent, ms: window.f2Page.lastRender.ms};
    });
    compare('frame 120 from the share link', sharedPicture, native120);

    // The Examples menu lists the gallery and loads a scene into the text.
    await opened.waitForFunction(() => document.getElementById('examples').options.length > 1, {timeout: 10000})
        .catch(() => {});
    const example = await opened.evaluate(() => {
      const menu = document.getElementById('examples');
      return {count: menu.options.length - 1, name: menu.options[1] && menu.options[1].value};
    });
    if (example.count < 1) problems.push('the Examples menu is empty');
    console.log(`${url}: ${example.count} examples, the first ${example.name}`);

    // Play advances frame by frame from 120, each a full picture; Pause stops.
    const before = await opened.evaluate(() => window.f2Page.fullRenders);
    await opened.click('#play');
    await opened.waitForFunction((n) => window.f2Page.fullRenders >= n + 4, {timeout: 60000}, before);
    await opened.click('#play');
    const played = await opened.evaluate(() => ({frame: window.f2Page.frame,
                                                 status: document.getElementById('status').textContent}));
    console.log(`${url}: playing reached frame ${played.frame}: ${played.status}`);
    if (!(played.frame >= 123)) problems.push(`playing from 120 reached only frame ${played.frame}`);
    if (!/frames\/s/.test(played.status)) problems.push(`no frame rate shown while playing: '${played.status}'`);

    if (example.count >= 1) {
      const rendered = await opened.evaluate(() => window.f2Page.fullRenders);
      await opened.select('#examples', example.name);
      await opened.waitForFunction((n) => window.f2Page.fullRenders > n && window.f2Page.lastRender.frame === 0,
                                   {timeout: 30000}, rendered);
      const loaded = await opened.evaluate(async (name) => {
        const file = await (await fetch(`examples/${name}`)).text();
        return {same: document.getElementById('scene').value === file, errors: document.querySelectorAll('#diagnostics li.error').length};
      }, example.name);
      if (!loaded.same || loaded.errors) problems.push(`the example ${example.name} was not loaded (or has errors)`);
    }
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
