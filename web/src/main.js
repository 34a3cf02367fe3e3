// The playground page: the scene text, its diagnostics, and the picture
// rendered by several workers, each with its own module instance and its own
// band of rows (no SharedArrayBuffer, so any static host serves it).
'use strict';

// A module using one wasm SIMD instruction (i8x16.splat etc.): it validates
// only where the browser has wasm SIMD. ?nosimd forces the fallback.
const kSimdProbe = new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0,
                                   65, 0, 253, 15, 253, 98, 11]);
const params = new URLSearchParams(location.search);
const useSimd = !params.has('nosimd') && WebAssembly.validate(kSimdProbe);
const workerCount = Math.max(1, Math.min(Number(params.get('workers')) || navigator.hardwareConcurrency || 2, 8));
const kDebounceMs = 150;

const textArea = document.getElementById('scene');
const canvas = document.getElementById('picture');
const context = canvas.getContext('2d');
const frameSlider = document.getElementById('frame');
const frameText = document.getElementById('frameText');
const playButton = document.getElementById('play');
const statusText = document.getElementById('status');
const diagnosticsList = document.getElementById('diagnostics');

const state = {
  workers: [],
  sceneId: 0,
  sceneOk: false,
  lastFrame: 0,
  frame: Number(params.get('frame')) || 0,
  playing: false,
  job: 0,            // the last render started
  busy: false,
  renders: 0,        // finished renders, previews included
  fullRenders: 0,    // finished full-resolution renders (tests wait on them)
  lastRender: null,  // {frame, scale, width, height, ms}
  lastPreviewMs: 0,  // the last quarter-resolution picture's time
};
window.f2Page = state;

function startWorkers() {
  const script = useSimd ? 'f2-simd.js' : 'f2.js';
  const loaded = [];
  for (let i = 0; i < workerCount; ++i) {
    const worker = new Worker('worker.js');
    worker.postMessage({type: 'load', script});
    loaded.push(new Promise((resolve) => {
      worker.addEventListener('message', function once(message) {
        if (message.data.type !== 'loaded') return;
        worker.removeEventListener('message', once);
        document.getElementById('build').textContent = `${message.data.build} build, ${workerCount} workers`;
        resolve();
      });
    }));
    worker.addEventListener('message', (message) => onWorkerMessage(message.data));
    state.workers.push(worker);
  }
  return Promise.all(loaded);
}

const sceneReplies = new Map();
function onWorkerMessage(m) {
  if (m.type === 'scene') {
    const waiting = sceneReplies.get(m.id);
    if (waiting && --waiting.left === 0) {
      sceneReplies.delete(m.id);
      waiting.resolve(m.result);
    }
  } else if (m.type === 'band') {
    onBand(m);
  }
}

/// Every worker reads the text; resolves with its diagnostics when all have.
function setScene(text) {
  const id = ++state.sceneId;
  return new Promise((resolve) => {
    sceneReplies.set(id, {left: state.workers.length, resolve});
    for (const worker of state.workers) worker.postMessage({type: 'scene', id, text});
  }).then((result) => ({id, result}));
}

function showDiagnostics(result) {
  diagnosticsList.replaceChildren();
  for (const d of result.diagnostics) {
    const item = document.createElement('li');
    item.className = d.severity;
    item.textContent = `${d.line}:${d.column}: ${d.severity}: ${d.message}`;
    diagnosticsList.append(item);
  }
}

// Progressive: after an edit or a scrub a quarter-resolution picture comes
// first (a sixteenth of the work), then the full one; playing renders full.
const kPreviewScale = 4;
const preview = document.createElement('canvas');

let band = null;     // the render in flight: its image and how many bands are left
let pending = [];    // the scales still to render for the current scene and frame
function render() {
  if (!state.sceneOk) return;
  pending = state.playing ? [1] : [kPreviewScale, 1];
  if (!state.busy) startNext();
}

function startNext() {
  const scale = pending.shift();
  if (scale === undefined) return;
  state.busy = true;
  const width = Math.ceil(canvas.width / scale), height = Math.ceil(canvas.height / scale);
  const job = ++state.job;
  // Bands of whole 32-row tiles, one per worker.
  const rowsPerBand = Math.ceil(height / state.workers.length / 32) * 32;
  band = {job, frame: state.frame, scale, width, height, left: 0, start: performance.now(),
          image: new ImageData(width, height)};
  state.workers.forEach((worker, i) => {
    const y0 = i * rowsPerBand, y1 = Math.min(height, y0 + rowsPerBand);
    if (y0 >= y1) return;
    ++band.left;
    worker.postMessage({type: 'render', job, frame: state.frame, width, height, y0, y1});
  });
}

function onBand(m) {
  if (!band || m.job !== band.job) return;
  if (m.pixels) band.image.data.set(m.pixels, m.y0 * band.width * 4);
  if (--band.left > 0) return;
  if (band.scale === 1) {
    context.putImageData(band.image, 0, 0);
  } else {
    preview.width = band.width;
    preview.height = band.height;
    preview.getContext('2d').putImageData(band.image, 0, 0);
    context.imageSmoothingEnabled = false;
    context.drawImage(preview, 0, 0, canvas.width, canvas.height);
  }
  const ms = performance.now() - band.start;
  state.lastRender = {frame: band.frame, scale: band.scale, width: band.width, height: band.height, ms};
  ++state.renders;
  if (band.scale !== 1) state.lastPreviewMs = ms;
  if (band.scale === 1) {
    ++state.fullRenders;
    statusText.textContent = `${ms.toFixed(0)} ms (${(1000 / ms).toFixed(1)} frames/s)`;
  }
  state.busy = false;
  if (pending.length) {
    startNext();
  } else if (state.playing) {
    state.frame = state.frame >= state.lastFrame ? 0 : state.frame + 1;
    showFrame();
    render();
  }
}

function showFrame() {
  frameSlider.value = String(state.frame);
  frameText.textContent = `frame ${state.frame} / ${state.lastFrame}`;
}

async function sceneChanged() {
  const {id, result} = await setScene(textArea.value);
  if (id !== state.sceneId) return;  // a newer text is on its way
  showDiagnostics(result);
  // With errors the workers keep the last good scene, and so does the picture.
  if (!result.ok) return;
  state.sceneOk = true;
  state.lastFrame = result.lastFrame;
  frameSlider.max = String(result.lastFrame);
  state.frame = Math.min(state.frame, result.lastFrame);
  showFrame();
  render();
}

let debounce = 0;
textArea.addEventListener('input', () => {
  clearTimeout(debounce);
  debounce = setTimeout(sceneChanged, kDebounceMs);
});
frameSlider.addEventListener('input', () => {
  state.frame = Number(frameSlider.value);
  showFrame();
  render();
});
playButton.addEventListener('click', () => {
  state.playing = !state.playing;
  playButton.textContent = state.playing ? 'Pause' : 'Play';
  if (state.playing) render();
});

// Share links: the scene deflated into the URL's fragment (never sent to a
// server), with the frame: #frame=120&scene=<base64url of deflate-raw>.
async function pipeBytes(bytes, stream) {
  return new Uint8Array(await new Response(new Blob([bytes]).stream().pipeThrough(stream)).arrayBuffer());
}
function toBase64Url(bytes) {
  let binary = '';
  for (const b of bytes) binary += String.fromCharCode(b);
  return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}
function fromBase64Url(text) {
  const binary = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  return Uint8Array.from(binary, (c) => c.charCodeAt(0));
}
async function shareLink() {
  const packed = await pipeBytes(new TextEncoder().encode(textArea.value), new CompressionStream('deflate-raw'));
  return `${location.origin}${location.pathname}${location.search}#frame=${state.frame}&scene=${toBase64Url(packed)}`;
}
/// The shared scene and frame of the URL's fragment, or null.
async function sharedScene() {
  const fragment = new URLSearchParams(location.hash.slice(1));
  if (!fragment.has('scene')) return null;
  const bytes = await pipeBytes(fromBase64Url(fragment.get('scene')), new DecompressionStream('deflate-raw'));
  return {text: new TextDecoder().decode(bytes), frame: Number(fragment.get('frame')) || 0};
}
document.getElementById('share').addEventListener('click', async () => {
  const link = await shareLink();
  history.replaceState(null, '', link);
  try {
    await navigator.clipboard.writeText(link);
    statusText.textContent = 'link copied';
  } catch (_) {
    statusText.textContent = 'the link is in the address bar';
  }
});

// The Examples menu: the gallery's scenes (examples/index.txt lists them).
const examples = document.getElementById('examples');
async function fillExamples() {
  const names = (await (await fetch('examples/index.txt')).text()).split('\n').filter((n) => n);
  for (const name of names) examples.append(new Option(name.replace(/\.f2$/, ''), name));
}
examples.addEventListener('change', async () => {
  if (!examples.value) return;
  textArea.value = await (await fetch(`examples/${examples.value}`)).text();
  examples.value = '';
  state.frame = 0;
  await sceneChanged();
});

async function start() {
  fillExamples().catch((error) => console.warn(`no examples: ${error}`));
  const shared = await sharedScene().catch(() => null);
  if (shared) state.frame = shared.frame;
  const [text] = await Promise.all([shared ? shared.text : fetch('demo.f2').then((r) => r.text()), startWorkers()]);
  textArea.value = text;
  await sceneChanged();
}
start().catch((error) => {
  statusText.textContent = `failed to start: ${error}`;
  console.error(error);
});
