// node page_check.js URL F2 DIR ERROR_LINE ERROR [SCREENSHOT.png]: opens the
// playground in Debian's chromium (puppeteer-core) and checks (docs/web.md)
// against `f2 render`'s pictures in DIR (frame0.png, frame0_aa.png: --aa 3,
// frame120.png), `f2 check`'s message ERROR for the line ERROR_LINE, and
// `f2 lsp` (F2) on the same texts, that
//  - the first full picture is `f2 render --frame 0` byte for byte, and the
//    anti-aliased one that follows while paused is `f2 render --aa 3`'s;
//  - typing ERROR_LINE into the editor lists ERROR and squiggles exactly the
//    ranges the language server marks (line, column and end column, UTF-16,
//    also after a non-ASCII character), and the picture stays; fixing the
//    text renders a quarter-resolution picture, then the full one again;
//  - completion after `/` offers the language server's items (the commands),
//    hovering a command shows its hover text, and the highlighting colours
//    each command by its group from the module's word lists;
//  - the frame slider at 120 shows `f2 render --frame 120`'s bytes; dragging
//    turns the view and "Scene camera" brings the same bytes back;
//  - the PNG download decodes to the canvas's pixels; the WebM download is a
//    WebM (with wasm SIMD only: it plays every frame);
//  - the share link opens, in another page, the same text at frame 120 with
//    the same pixels; Play advances the frames and shows the frame rate;
//    the Examples menu loads a gallery scene; ?embed shows no editor;
//  - no page logged an error or threw an exception.
// Every wait is for a state the page exposes (window.f2Page), not a time.
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const puppeteer = require('puppeteer-core');
const {readPng} = require('./png');
const {startLsp} = require('./lsp_client');

const kAntialias = 3;  // the page's default ?aa
const kUri = 'file:///playground/scene.f2';

async function main() {
  const [url, f2, dir, errorLine, expectedError, screenshot] = process.argv.slice(2);
  const native = readPng(fs.readFileSync(path.join(dir, 'frame0.png')));
  const nativeAa = readPng(fs.readFileSync(path.join(dir, 'frame0_aa.png')));
  const native120 = readPng(fs.readFileSync(path.join(dir, 'frame120.png')));
  const simd = !url.includes('nosimd');
  const browser = await puppeteer.launch({
    executablePath: process.env.F2_CHROMIUM || '/usr/bin/chromium',
    args: ['--no-sandbox', '--headless=new'],
  });
  const lsp = await startLsp(f2);
  const problems = [];
  const check = (ok, what) => {
    if (!ok) problems.push(what);
  };
  // A page that keeps a copy of the last full picture without anti-aliasing
  // (window.plainPicture): the anti-aliased one replaces it on the canvas.
  const openPage = async (address, name) => {
    const page = await browser.newPage();
    page.on('console', (m) => {
      if (m.type() === 'error') problems.push(`${name}: console error: ${m.text()}`);
    });
    page.on('pageerror', (e) => problems.push(`${name}: uncaught: ${e.message}`));
    await page.setViewport({width: 1400, height: 700});
    await page.evaluateOnNewDocument(() => {
      window.addEventListener('f2picture', (event) => {
        if (event.detail.scale !== 1 || event.detail.antialias !== 1) return;
        const canvas = document.getElementById('picture');
        window.plainPicture = {...event.detail,
                               data: canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data};
      });
    });
    await page.goto(address);
    return page;
  };
  // `condition`: an expression of `arg`.
  const settled = (page, condition = 'true', arg = null) =>
    page.waitForFunction(`((arg) => window.f2Page && window.f2Page.settled && window.f2Page.editor && ` +
                         `(${condition}))(${JSON.stringify(arg)})`, {timeout: 120000});
  const canvasBytes = (page) => page.evaluate(() => {
    const canvas = document.getElementById('picture');
    const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    return {width: canvas.width, height: canvas.height, pixels: Array.from(data),
            build: document.getElementById('build').textContent, render: window.f2Page.lastRender,
            renders: window.f2Page.renders, fullRenders: window.f2Page.fullRenders,
            previewMs: window.f2Page.lastPreviewMs};
  });
  const plainBytes = (page) => page.evaluate(() => ({width: 640, height: 480, frame: window.plainPicture.frame,
                                                      pixels: Array.from(window.plainPicture.data)}));
  const differing = (a, b) => {
    let count = 0, largest = 0;
    for (let p = 0; p < a.length / 4; ++p) {
      let d = 0;
      for (let k = 0; k < 4; ++k) d = Math.max(d, Math.abs(a[p * 4 + k] - b[p * 4 + k]));
      if (d > 0) ++count;
      largest = Math.max(largest, d);
    }
    return {count, largest};
  };
  const compare = (what, result, expected) => {
    if (result.width !== expected.width || result.height !== expected.height) {
      problems.push(`${what}: canvas ${result.width}x${result.height}, f2 render ${expected.width}x${expected.height}`);
      return;
    }
    const d = differing(result.pixels, expected.rgba);
    console.log(`${url}: ${what}: ${d.count} of ${result.width * result.height} pixels differ from f2 render, ` +
                `by at most ${d.largest}`);
    check(d.count === 0, `${what}: the canvas differs from f2 render`);
  };
  const setText = (page, text) => page.evaluate((t) => window.f2Page.editor.setText(t), text);
  const moveToEnd = (page) => page.evaluate(() => {
    const view = window.f2Page.editor.view;
    view.focus();
    view.dispatch({selection: {anchor: view.state.doc.length}});
  });
  /// The editor's squiggles against `f2 lsp`'s diagnostics of the same text.
  const compareSquiggles = async (page, what) => {
    const {text, squiggles} = await page.evaluate(() => ({text: window.f2Page.editor.text(),
                                                          squiggles: window.f2Page.editor.squiggles()}));
    const server = (await lsp.open(kUri, text)).map((d) => ({
      line: d.range.start.line + 1, column: d.range.start.character + 1, endLine: d.range.end.line + 1,
      endColumn: d.range.end.character + 1, message: d.message}));
    console.log(`${url}: ${what}: squiggles ${JSON.stringify(squiggles.map((s) => [s.line, s.column, s.endColumn]))}` +
                `, f2 lsp ${JSON.stringify(server.map((s) => [s.line, s.column, s.endColumn]))}`);
    check(squiggles.length === server.length && squiggles.length > 0,
          `${what}: ${squiggles.length} squiggles, f2 lsp marks ${server.length}`);
    server.forEach((s, i) => {
      const e = squiggles[i];
      if (!e) return;
      check(e.line === s.line && e.column === s.column && e.endLine === s.endLine && e.endColumn === s.endColumn &&
            e.message.endsWith(s.message),
            `${what}: squiggle ${JSON.stringify(e)}, f2 lsp ${JSON.stringify(s)}`);
    });
    const drawn = await page.evaluate(() => document.querySelectorAll('.cm-lintRange-error').length);
    check(drawn > 0, `${what}: no squiggle drawn`);
  };

  try {
    const page = await openPage(url, 'page');
    await settled(page, 'window.f2Page.lastRender.antialias === arg', kAntialias);
    const first = await canvasBytes(page);
    console.log(`${url}: ${first.build}; the anti-aliased picture in ${first.render.ms.toFixed(0)} ms`);
    compare('frame 0', await plainBytes(page), native);
    compare(`frame 0 anti-aliased ${kAntialias}x${kAntialias} when paused`, first, nativeAa);
    if (screenshot) await page.screenshot({path: screenshot});
    const text = await page.evaluate(() => window.f2Page.editor.text());

    // An error typed into the editor: f2 check's message, f2 lsp's squiggle, the picture kept.
    await moveToEnd(page);
    await page.keyboard.type(`${text.endsWith('\n') ? '' : '\n'}${errorLine}`);
    await page.waitForFunction((expected) => window.f2Page.editor.text().endsWith(expected) &&
                                   window.f2Page.lastDiagnostics && window.f2Page.lastDiagnostics.length > 0 &&
                                   document.querySelectorAll('#diagnostics li').length > 0 &&
                                   window.f2Page.lastSceneText === window.f2Page.editor.text(),
                               {timeout: 30000}, errorLine);
    const shown = await page.evaluate(() => document.querySelector('#diagnostics li').textContent);
    console.log(`${url}: with '${errorLine}': ${shown}`);
    check(shown === expectedError, `the page shows '${shown}', f2 check '${expectedError}'`);
    await compareSquiggles(page, `'${errorLine}' typed`);
    const kept = await canvasBytes(page);
    check(kept.renders === first.renders, 'the picture was rendered again from a scene with an error');
    compare('the picture kept while the text has an error', kept, nativeAa);
    // Errors after a non-ASCII character: the squiggles count UTF-16 units, as f2 lsp does.
    await setText(page, text);
    await settled(page, 'window.f2Page.lastSceneText === window.f2Page.editor.text()');
    await moveToEnd(page);
    await page.keyboard.type('/caption c "é" 1 2 3 x');
    await page.waitForFunction(() => window.f2Page.lastSceneText === window.f2Page.editor.text() &&
                                   window.f2Page.lastDiagnostics.length > 1, {timeout: 30000});
    await compareSquiggles(page, 'a line with é');

    // Fixed: a quarter-resolution picture, then the full one.
    const before = await canvasBytes(page);
    await setText(page, text);
    await settled(page, 'window.f2Page.fullRenders > arg && !document.querySelector("#diagnostics li")',
                  before.fullRenders);
    const fixed = await canvasBytes(page);
    check(fixed.renders >= before.renders + 3, 'no quarter-resolution picture before the full ones');
    console.log(`${url}: the text fixed: a quarter-resolution picture ${fixed.previewMs.toFixed(0)} ms after the ` +
                'edit reached the workers');
    compare('frame 0 again after the fix', await plainBytes(page), native);
    compare('frame 0 anti-aliased after the fix', fixed, nativeAa);

    // Completion after '/': the language server's items, the commands.
    await moveToEnd(page);
    await page.keyboard.type('/');
    await page.waitForSelector('.cm-tooltip-autocomplete li', {timeout: 30000});
    const offered = await page.evaluate(() => Array.from(document.querySelectorAll('.cm-tooltip-autocomplete li'),
                                                         (li) => li.querySelector('.cm-completionLabel').textContent));
    const typed = await page.evaluate(() => window.f2Page.editor.text());
    await lsp.open(kUri, typed);
    const lines = typed.split('\n');
    const items = await lsp.request('textDocument/completion', {textDocument: {uri: kUri},
                                                                position: {line: lines.length - 1, character: 1}});
    const expectedLabels = (Array.isArray(items) ? items : items.items).map((i) => i.label);
    console.log(`${url}: completion after '/' offers ${offered.length} items (${offered.slice(0, 4).join(' ')} …), ` +
                `f2 lsp ${expectedLabels.length}`);
    check(JSON.stringify([...offered].sort()) === JSON.stringify([...expectedLabels].sort()),
          'completion after / differs from f2 lsp');
    const lists = await page.evaluate(() => window.f2Page.languageLists.commands);
    check(lists.every((c) => offered.includes(`/${c}`)), 'completion after / misses commands');
    await page.keyboard.press('Escape');
    await setText(page, text);
    await settled(page, 'window.f2Page.lastSceneText === window.f2Page.editor.text()');

    // Highlighting from the module's word lists (the TextMate grammar's):
    // every command in its group's colour, an unknown one as invalid.
    const colours = await page.evaluate(async () => {
      const {editor, languageLists: lists} = window.f2Page;
      const words = [...lists.commands, 'no_such_command'];
      editor.setText(words.map((w) => `/${w} x`).join('\n'));
      await new Promise(requestAnimationFrame);
      const shown = {};
      for (const line of document.querySelectorAll('#editor .cm-line')) {
        const span = line.querySelector('span');
        if (span) shown[span.textContent] = getComputedStyle(span).color;
      }
      const creating = new Set([...lists.creating, ...lists['variable-commands'], ...lists['path-commands']]);
      return words.map((w) => ({word: w, colour: shown[`/${w}`],
                                expected: w === 'no_such_command' ? 'rgb(244, 71, 71)'
                                          : creating.has(w) ? 'rgb(197, 134, 192)' : 'rgb(86, 156, 214)'}));
    });
    const shownWords = colours.filter((c) => c.colour);
    const wrong = shownWords.filter((c) => c.colour !== c.expected);
    console.log(`${url}: highlighting: ${shownWords.length} of ${colours.length} command lines drawn, ` +
                `${wrong.length} in another colour than their group's`);
    check(shownWords.length >= 10 && wrong.length === 0,
          `highlighting: ${JSON.stringify(wrong.slice(0, 3))} (${shownWords.length} lines drawn)`);
    await setText(page, text);
    await settled(page, 'window.f2Page.lastSceneText === window.f2Page.editor.text()');

    // Hover on `/camera`: f2 lsp's hover text.
    const cameraLine = text.split('\n').findIndex((l) => l.startsWith('/camera'));
    const point = await page.evaluate((line) => {
      const view = window.f2Page.editor.view;
      const at = view.state.doc.line(line + 1).from + 2;
      view.dispatch({effects: window.F2Editor.scrollTo(at)});
      const box = view.coordsAtPos(at);
      return {x: box.left + 2, y: (box.top + box.bottom) / 2};
    }, cameraLine);
    await page.mouse.move(point.x, point.y);
    await page.waitForSelector('.cm-f2-hover', {timeout: 30000});
    const hoverText = await page.evaluate(() => document.querySelector('.cm-f2-hover').textContent);
    await lsp.open(kUri, text);
    const hover = await lsp.request('textDocument/hover', {textDocument: {uri: kUri},
                                                           position: {line: cameraLine, character: 2}});
    // The markdown's text without its markup and spaces (the tooltip sets code blocks apart by layout).
    const plain = (s) => s.replace(/```f2\n?|```|`|\*\*/g, '').replace(/\s+/g, '');
    console.log(`${url}: hover on /camera: ${hoverText.slice(0, 80)}…`);
    check(hover && plain(hoverText) === plain(hover.contents.value), 'the hover text is not f2 lsp\'s');
    await page.mouse.move(5, 5);

    // Scrub to 120.
    const scrubbed = await page.evaluate(() => window.f2Page.fullRenders);
    await page.evaluate(() => {
      const slider = document.getElementById('frame');
      slider.value = '120';
      slider.dispatchEvent(new Event('input'));
    });
    await settled(page, 'window.f2Page.fullRenders > arg && window.f2Page.lastRender.frame === 120',
                  scrubbed);
    compare('frame 120 from the slider', await plainBytes(page), native120);
    const at120 = await canvasBytes(page);

    // Orbit: a drag turns the view; "Scene camera" brings the scene's camera back.
    const box = await (await page.$('#picture')).boundingBox();
    await page.mouse.move(box.x + 320, box.y + 240);
    await page.mouse.down();
    await page.mouse.move(box.x + 420, box.y + 260, {steps: 4});
    await page.mouse.up();
    await settled(page, 'window.f2Page.lastRender.view.yaw !== 0 && window.f2Page.lastRender.antialias > 1');
    const turned = await canvasBytes(page);
    const moved = differing(turned.pixels, at120.pixels).count;
    console.log(`${url}: dragged 100 pixels: yaw ${turned.render.view.yaw}, pitch ${turned.render.view.pitch}, ` +
                `${moved} pixels changed`);
    check(moved > 10000, 'dragging did not turn the view');
    await page.click('#resetView');
    await settled(page, 'window.f2Page.lastRender.view.yaw === 0 && window.f2Page.lastRender.antialias > 1');
    check(differing((await canvasBytes(page)).pixels, at120.pixels).count === 0,
          'the scene camera after a drag is not the picture before it');

    // Share: the link opens the same text at the same frame, the same pixels.
    await page.click('#share');
    await page.waitForFunction(() => location.hash.includes('scene='), {timeout: 30000});
    const link = page.url();
    const opened = await openPage(link, 'shared page');
    await settled(opened, 'window.f2Page.lastRender.antialias > 1');
    const shared = await opened.evaluate(() => ({text: window.f2Page.editor.text(),
                                                 slider: document.getElementById('frame').value}));
    console.log(`${url}: a share link of ${link.length} characters opens frame ${shared.slider}`);
    check(shared.text === text, 'the share link opened another text');
    check(shared.slider === '120', `the share link opened frame ${shared.slider}, not 120`);
    compare('frame 120 from the share link', await plainBytes(opened), native120);
    check(differing((await canvasBytes(opened)).pixels, at120.pixels).count === 0,
          'the share link\'s anti-aliased picture differs');

    // The PNG download holds the canvas's pixels (in the first page: a background page does not render).
    await page.bringToFront();
    const downloads = fs.mkdtempSync(path.join(os.tmpdir(), 'f2-page-'));
    const cdp = await browser.target().createCDPSession();
    await cdp.send('Browser.setDownloadBehavior', {behavior: 'allow', downloadPath: downloads, eventsEnabled: true});
    const downloaded = () => new Promise((resolve) => {
      const files = new Map();
      cdp.on('Browser.downloadWillBegin', (e) => files.set(e.guid, e.suggestedFilename));
      cdp.on('Browser.downloadProgress', (e) => {
        if (e.state === 'completed') resolve(path.join(downloads, files.get(e.guid)));
      });
    });
    let done = downloaded();
    await page.click('#png');
    const png = readPng(fs.readFileSync(await done));
    const shownNow = await canvasBytes(page);
    const pngDiff = differing(png.rgba, shownNow.pixels);
    console.log(`${url}: the PNG download: ${png.width}x${png.height}, ${pngDiff.count} pixels differ from the canvas`);
    check(png.width === 640 && png.height === 480 && pngDiff.count === 0, 'the PNG download is not the canvas');
    if (simd) {
      done = downloaded();
      await page.click('#webm');
      const webm = fs.readFileSync(await done);
      const frames = await page.evaluate(() => window.f2Page.lastFrame + 1);
      console.log(`${url}: the WebM download of ${frames} frames: ${webm.length} bytes`);
      check(webm.length > 1000 && webm.readUInt32BE(0) === 0x1a45dfa3, 'the WebM download is not a WebM file');
    }
    fs.rmSync(downloads, {recursive: true, force: true});

    // Play advances frame by frame from 120, each a full picture, and shows the frame rate.
    await opened.bringToFront();
    const played = await opened.evaluate(() => window.f2Page.fullRenders);
    await opened.click('#play');
    await opened.waitForFunction((n) => window.f2Page.fullRenders >= n + 4 && window.f2Page.playFps > 0,
                                 {timeout: 60000}, played);
    await opened.click('#play');
    const playing = await opened.evaluate(() => ({frame: window.f2Page.frame,
                                                  status: document.getElementById('status').textContent}));
    console.log(`${url}: playing reached frame ${playing.frame}: ${playing.status}`);
    check(playing.frame >= 123, `playing from 120 reached only frame ${playing.frame}`);
    check(/frames\/s/.test(playing.status), `no frame rate shown while playing: '${playing.status}'`);

    // The Examples menu lists the gallery and loads a scene into the editor.
    await opened.waitForFunction(() => document.getElementById('examples').options.length > 1, {timeout: 10000})
        .catch(() => {});
    const example = await opened.evaluate(() => {
      const menu = document.getElementById('examples');
      return {count: menu.options.length - 1, name: menu.options[1] && menu.options[1].value};
    });
    check(example.count >= 1, 'the Examples menu is empty');
    if (example.count >= 1) {
      await settled(opened);
      const rendered = await opened.evaluate(() => window.f2Page.fullRenders);
      await opened.select('#examples', example.name);
      await settled(opened, 'window.f2Page.fullRenders > arg && window.f2Page.lastRender.frame === 0',
                    rendered);
      const loaded = await opened.evaluate(async (name) => {
        const file = await (await fetch(`examples/${name}`)).text();
        return {same: window.f2Page.editor.text() === file, errors: document.querySelectorAll('#diagnostics li.error').length};
      }, example.name);
      console.log(`${url}: ${example.count} examples; ${example.name} loaded`);
      check(loaded.same && !loaded.errors, `the example ${example.name} was not loaded (or has errors)`);
    }

    // ?embed: the player only.
    const embedded = await openPage(url + (url.includes('?') ? '&' : '?') + 'embed', 'embedded page');
    await settled(embedded, 'window.f2Page.lastRender.antialias > 1');
    const visible = await embedded.evaluate(() => {
      const shows = (id) => document.getElementById(id).getClientRects().length > 0;
      return {editor: shows('editor'), canvas: shows('picture'), play: shows('play'), share: shows('share')};
    });
    console.log(`${url}&embed: ${JSON.stringify(visible)}`);
    check(!visible.editor && !visible.share && visible.canvas && visible.play, '?embed does not show the player only');
    compare('frame 0 anti-aliased in ?embed', await canvasBytes(embedded), nativeAa);
  } finally {
    await browser.close();
    await lsp.close();
  }
  for (const p of problems) console.log(`FAIL: ${p}`);
  if (problems.length) process.exitCode = 1;
}

main().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
