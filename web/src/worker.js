// One render worker: its own instance of the module (wasm SIMD or the
// fallback, as the page chose), rendering the bands of rows it is handed,
// or (the page's language worker) answering the editor's requests.
'use strict';
let f2 = null;
const pending = [];

function handle(message) {
  const m = message.data;
  if (m.type === 'scene') {
    const result = f2.setScene(m.text);
    postMessage({type: 'scene', id: m.id, result});
  } else if (m.type === 'lsp') {
    postMessage({type: 'lsp', id: m.id, result: f2.lsp(m.method, m.params)});
  } else if (m.type === 'render') {
    const start = performance.now();
    const pixels = f2.render(m.frame, m.width, m.height, m.y0, m.y1, m.view);
    const ms = performance.now() - start;
    const buffer = pixels ? pixels.buffer : null;
    postMessage({type: 'band', job: m.job, worker: m.worker, y0: m.y0, y1: m.y1, pixels, ms}, buffer ? [buffer] : []);
  }
}

onmessage = (message) => {
  if (message.data.type === 'load') {
    importScripts('f2_module.js', message.data.script);
    createF2Module().then((instance) => {
      f2 = wrapF2Module(instance);
      postMessage({type: 'loaded', build: f2.buildName()});
      pending.splice(0).forEach(handle);
    });
  } else if (f2) {
    handle(message);
  } else {
    pending.push(message);
  }
};
