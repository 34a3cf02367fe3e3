// The playground page: the editor (editor.js), the diagnostics, and the
// picture rendered by several workers, each with its own module instance,
// taking chunks of rows (no SharedArrayBuffer, so any static host serves it).
'use strict';

// A module using one wasm SIMD instruction (i8x16.splat etc.): it validates
// only where the browser has wasm SIMD. ?nosimd forces the fallback.
const kSimdProbe = new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0,
                                   65, 0, 253, 15, 253, 98, 11]);
const params = new URLSearchParams(location.search);
const useSimd = !params.has('nosimd') && WebAssembly.validate(kSimdProbe);
const workerCount = Math.max(1, Math.min(Number(params.get('workers')) || navigator.hardwareConcurrency || 2, 8));
// The paused picture's samples per pixel: N x N, as `f2 render --aa N`.
const kPausedAntialias = Math.max(1, Math.min(Number(params.get('aa')) || 3, 16));
const embed = params.has('embed');
// ?size=WxH: the picture's size (default 640x480).
const size = /^(\d+)x(\d+)$/.exec(params.get('size') || '');
if (embed) document.body.classList.add('embed');

let editor = null;  // the CodeMirror editor (editor.js), made once the module's word lists are in
const canvas = document.getElementById('picture');
if (size) [canvas.width, canvas.height] = [Math.min(Number(size[1]), 4096), Math.min(Number(size[2]), 4096)];
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
  renders: 0,        // finished renders, previews included
  fullRenders: 0,    // finished full-resolution renders (tests wait on them)
  lastRender: null,  // {frame, scale, antialias, width, height, ms, view}
  lastPreviewMs: 0,  // the last quarter-resolution picture's time
  settled: false,    // the last picture asked for is on the canvas (anti-aliased when paused)
  view: {yaw: 0, pitch: 0, zoom: 1},  // the mouse's look-around; 0, 0, 1: the scene's camera
  playFps: 0,        // frames per second while playing (the last second)
  lastSceneMs: 0,    // from an edit's text to its diagnostics from every worker
  editedAt: 0,       // when the last edit was typed (performance.now())
  lastEditMs: 0,     // from that keystroke to the quarter-resolution picture on the canvas
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

// The language worker: one more module instance that answers the editor's
// completion and hover (f2_lsp), so they never wait for a render.
let languageWorker = null;
let languageRequest = 0;
const languageReplies = new Map();
function startLanguageWorker() {
  languageWorker = new Worker('worker.js');
  languageWorker.postMessage({type: 'load', script: useSimd ? 'f2-simd.js' : 'f2.js'});
  languageWorker.addEventListener('message', (message) => {
    const m = message.data;
    if (m.type !== 'lsp') return;
    languageReplies.get(m.id)(m.result);
    languageReplies.delete(m.id);
  });
}
function lsp(method, params) {
  const id = ++languageRequest;
  return new Promise((resolve) => {
    languageReplies.set(id, resolve);
    languageWorker.postMessage({type: 'lsp', id, method, params});
  });
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
  // Chunks handed out after the text would be of the new scene: the picture
  // in flight starts again after it (of the last good scene, if this one has errors).
  const live = liveBands();
  for (const b of live) b.cancelled = true;
  const reply = new Promise((resolve) => {
    sceneReplies.set(id, {left: state.workers.length, resolve});
    for (const worker of state.workers) worker.postMessage({type: 'scene', id, text});
  }).then((result) => ({id, result}));
  if (live.length) {
    pending.unshift({scale: live[0].scale, antialias: live[0].antialias});
    startNext();
  }
  return reply;
}

function showDiagnostics(result) {
  editor.setDiagnostics(result.diagnostics);
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

let bands = [];      // the pictures in flight, oldest first: their images, rows handed out, chunks out
let pending = [];    // the pictures still to render for the current scene and frame: {scale, antialias}
const liveBands = () => bands.filter((b) => !b.cancelled);
function render() {
  if (!state.sceneOk) return;
  state.settled = false;
  pending = state.playing ? [{scale: 1, antialias: 1}]
                          : [{scale: kPreviewScale, antialias: 1}, {scale: 1, antialias: 1}];
  if (!state.playing && kPausedAntialias > 1) pending.push({scale: 1, antialias: kPausedAntialias});
  if (dragging) pending = [{scale: kPreviewScale, antialias: 1}];
  // The pictures in flight are dropped: their chunks not yet handed out never are.
  for (const b of bands) b.cancelled = true;
  startNext();
}

// The workers take chunks of rows, the next as each returns: a busy core (the
// machine's other work) gets fewer, and a new picture waits for the chunks
// already handed out, not for a whole anti-aliased frame. Two chunks a
// worker, so it starts the next while the page takes the last; one while
// anti-aliasing, whose chunks are long. While playing, the next frame's
// chunks follow the last of this frame's, so no worker waits for the page
// to show a frame.
const kChunkRows = 32;  // one row of the renderer's tiles (kTileSize)
let held = [];          // chunks each worker holds
function startNext() {
  const next = pending.shift();
  if (next === undefined) {
    if (!liveBands().length) state.settled = true;
    return;
  }
  addBand(next, state.frame);
  handOut();
}

function addBand({scale, antialias}, frame) {
  const width = Math.ceil(canvas.width / scale), height = Math.ceil(canvas.height / scale);
  const band = {job: ++state.job, frame, scale, antialias, width, height, start: performance.now(),
                image: new ImageData(width, height), view: {...state.view}, bandMs: [], nextRow: 0, out: 0,
                cancelled: false};
  bands.push(band);
  return band;
}

/// The picture the next chunk comes from: the oldest with rows left, or,
/// while playing, the next frame once the last one's rows are all handed out.
function nextBand() {
  const live = liveBands();
  const open = live.find((b) => b.nextRow < b.height);
  if (open || !state.playing || live.length !== 1 || live[0].scale !== 1) return open;
  const last = live[0];
  if (recorder && last.frame >= state.lastFrame) return undefined;  // the recording ends there
  return addBand({scale: 1, antialias: 1}, last.frame >= state.lastFrame ? 0 : last.frame + 1);
}

function handOut() {
  if (held.length !== state.workers.length) held = state.workers.map(() => 0);
  for (let k = 0; k < 2; ++k) {
    state.workers.forEach((worker, i) => {
      const band = nextBand();
      if (!band || held[i] >= (band.antialias > 1 ? 1 : 2)) return;
      const y0 = band.nextRow, y1 = Math.min(band.height, y0 + kChunkRows);
      band.nextRow = y1;
      ++band.out;
      ++held[i];
      worker.postMessage({type: 'render', job: band.job, worker: i, frame: band.frame, width: band.width,
                          height: band.height, y0, y1, view: {antialias: band.antialias, ...band.view}});
    });
  }
}

const playTimes = [];  // when each frame played showed, for the frame rate of the last second
function onBand(m) {
  --held[m.worker];
  const band = bands.find((b) => b.job === m.job);
  if (band) {
    --band.out;
    if (!band.cancelled && m.pixels) band.image.data.set(m.pixels, m.y0 * band.width * 4);
    band.bandMs.push(m.ms);
  }
  // Finished pictures go on the canvas in the order they were asked for.
  while (bands.length && bands[0].out === 0 && (bands[0].cancelled || bands[0].nextRow >= bands[0].height)) {
    const done = bands.shift();
    if (!done.cancelled) show(done);
  }
  if (!liveBands().length) {
    if (recorder && state.playing && state.frame >= state.lastFrame) {
      recorder.finish();
      return;
    }
    if (pending.length) {
      startNext();
    } else if (state.playing) {
      state.frame = state.frame >= state.lastFrame ? 0 : state.frame + 1;
      showFrame();
      render();
    } else {
      state.settled = true;
    }
  }
  handOut();
}

function show(band) {
  if (band.scale === 1) {
    context.putImageData(band.image, 0, 0);
  } else {
    preview.width = band.width;
    preview.height = band.height;
    preview.getContext('2d').putImageData(band.image, 0, 0);
    context.imageSmoothingEnabled = false;
    context.drawImage(preview, 0, 0, canvas.width, canvas.height);
  }
  if (recorder) recorder.frameShown();
  if (state.playing && band.frame !== state.frame) {
    state.frame = band.frame;
    showFrame();
  }
  const now = performance.now();
  const ms = now - band.start;
  state.lastRender = {frame: band.frame, scale: band.scale, antialias: band.antialias, width: band.width,
                      height: band.height, ms, view: band.view, bandMs: band.bandMs};
  ++state.renders;
  if (band.scale !== 1) {
    state.lastPreviewMs = ms;
    if (state.editedAt) {
      state.lastEditMs = now - state.editedAt;
      state.editedAt = 0;
    }
  } else {
    ++state.fullRenders;
    if (state.playing) {
      playTimes.push(now);
      while (playTimes.length && playTimes[0] < now - 1000) playTimes.shift();
      state.playFps = playTimes.length > 1 ? (playTimes.length - 1) * 1000 / (now - playTimes[0]) : 0;
      statusText.textContent = `${state.playFps.toFixed(1)} frames/s (${ms.toFixed(0)} ms a frame)`;
    } else {
      statusText.textContent = band.antialias > 1 ? `anti-aliased ${band.antialias}×${band.antialias}: ${ms.toFixed(0)} ms`
                                                  : `${ms.toFixed(0)} ms`;
    }
  }
  // For tests and tools: a picture is on the canvas (state.lastRender says which).
  window.dispatchEvent(new CustomEvent('f2picture',
                                       {detail: {frame: band.frame, scale: band.scale, antialias: band.antialias,
                                                 view: band.view}}));
}

function showFrame() {
  frameSlider.value = String(state.frame);
  frameText.textContent = `frame ${state.frame} / ${state.lastFrame}`;
}

async function sceneChanged() {
  const start = performance.now();
  const text = editor.text();
  const {id, result} = await setScene(text);
  if (id !== state.sceneId) return;  // a newer text is on its way
  state.lastSceneMs = performance.now() - start;
  state.lastSceneText = text;
  showDiagnostics(result);
  state.lastDiagnostics = result.diagnostics;
  // With errors the workers keep the last good scene, and so does the picture.
  if (!result.ok) {
    state.editedAt = 0;
    return;
  }
  state.sceneOk = true;
  state.lastFrame = result.lastFrame;
  frameSlider.max = String(result.lastFrame);
  state.frame = Math.min(state.frame, result.lastFrame);
  showFrame();
  render();
}

// Each edit goes to the workers at once unless one is on its way; then the
// newest text follows when that one is answered (no fixed pause for typing).
let sceneInFlight = false, sceneAgain = false;
async function runScene() {
  sceneInFlight = true;
  await sceneChanged();
  sceneInFlight = false;
  if (sceneAgain) {
    sceneAgain = false;
    runScene();
  }
}
function textEdited() {
  state.editedAt = performance.now();
  if (sceneInFlight) sceneAgain = true;
  else runScene();
}
frameSlider.addEventListener('input', () => {
  state.frame = Number(frameSlider.value);
  showFrame();
  render();
});
function setPlaying(playing) {
  state.playing = playing;
  playButton.textContent = state.playing ? 'Pause' : 'Play';
  playTimes.length = 0;
  render();
}
playButton.addEventListener('click', () => setPlaying(!state.playing));

// Orbit: dragging on the picture turns the view about the scene (the
// viewer's look-around, core/render/orbit_camera.h), the wheel moves closer;
// the scene text keeps its camera. Quarter resolution while dragging.
let dragging = null;
const kDegreesPerPixel = 0.4;
canvas.addEventListener('pointerdown', (event) => {
  dragging = {x: event.clientX, y: event.clientY, yaw: state.view.yaw, pitch: state.view.pitch};
  canvas.setPointerCapture(event.pointerId);
});
canvas.addEventListener('pointermove', (event) => {
  if (!dragging) return;
  state.view.yaw = dragging.yaw - (event.clientX - dragging.x) * kDegreesPerPixel;
  state.view.pitch = dragging.pitch + (event.clientY - dragging.y) * kDegreesPerPixel;
  render();
});
canvas.addEventListener('pointerup', () => {
  dragging = null;
  render();
});
canvas.addEventListener('wheel', (event) => {
  event.preventDefault();
  state.view.zoom *= Math.exp(event.deltaY * 0.001);
  render();
}, {passive: false});
document.getElementById('resetView').addEventListener('click', () => {
  state.view = {yaw: 0, pitch: 0, zoom: 1};
  render();
});

// Downloads: the picture shown as a PNG; the animation as a WebM, recorded
// from the canvas (MediaRecorder) while it plays every frame once at full
// resolution, one video frame per picture.
function download(blob, name) {
  const link = document.createElement('a');
  link.href = URL.createObjectURL(blob);
  link.download = name;
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 10000);
}
document.getElementById('png').addEventListener('click', () => {
  canvas.toBlob((blob) => download(blob, `f2-frame${state.frame}.png`), 'image/png');
});
let recorder = null;
document.getElementById('webm').addEventListener('click', () => {
  if (recorder || !state.sceneOk) return;
  if (typeof MediaRecorder === 'undefined' || !MediaRecorder.isTypeSupported('video/webm')) {
    statusText.textContent = 'this browser cannot record WebM';
    return;
  }
  const stream = canvas.captureStream(0);
  const track = stream.getVideoTracks()[0];
  const media = new MediaRecorder(stream, {mimeType: 'video/webm'});
  const chunks = [];
  media.ondataavailable = (event) => chunks.push(event.data);
  media.onstop = () => {
    download(new Blob(chunks, {type: 'video/webm'}), 'f2-animation.webm');
    state.webmBytes = chunks.reduce((sum, chunk) => sum + chunk.size, 0);
    statusText.textContent = `WebM of ${state.lastFrame + 1} frames`;
  };
  recorder = {
    frameShown: () => track.requestFrame(),
    finish() {
      recorder = null;
      media.stop();
      setPlaying(false);
    },
  };
  media.start();
  state.frame = 0;
  showFrame();
  setPlaying(true);
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
  const packed = await pipeBytes(new TextEncoder().encode(editor.text()), new CompressionStream('deflate-raw'));
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
  const text = await (await fetch(`examples/${examples.value}`)).text();
  examples.value = '';
  state.frame = 0;
  editor.setText(text);  // textEdited renders it
});

async function start() {
  if (!embed) fillExamples().catch((error) => console.warn(`no examples: ${error}`));
  const shared = await sharedScene().catch(() => null);
  if (shared) state.frame = shared.frame;
  startLanguageWorker();
  const [text, lists] = await Promise.all([shared ? shared.text : fetch('demo.f2').then((r) => r.text()),
                                           lsp('f2/languageLists', {}), startWorkers()]);
  state.languageLists = lists;
  editor = window.F2Editor.create(document.getElementById('editor'), {text, lists, lsp, onChange: textEdited});
  state.editor = editor;
  await runScene();
}
start().catch((error) => {
  statusText.textContent = `failed to start: ${error}`;
  console.error(error);
});
