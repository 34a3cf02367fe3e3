// A minimal client of `f2 lsp` (JSON-RPC over stdio, Content-Length framing)
// for the page test: what the language server says about a text, to compare
// with the page's editor.
'use strict';
const {spawn} = require('child_process');

/// Starts `f2 lsp`; resolves with {request(method, params), diagnostics(uri), close()}.
async function startLsp(f2) {
  const server = spawn(f2, ['lsp'], {stdio: ['pipe', 'pipe', 'inherit']});
  let buffer = Buffer.alloc(0);
  let nextId = 0;
  const replies = new Map();
  const published = new Map();  // uri -> diagnostics
  const waiting = [];           // {uri, resolve}
  server.stdout.on('data', (chunk) => {
    buffer = Buffer.concat([buffer, chunk]);
    for (;;) {
      const end = buffer.indexOf('\r\n\r\n');
      if (end < 0) return;
      const length = Number(/Content-Length: (\d+)/i.exec(buffer.toString('latin1', 0, end))[1]);
      if (buffer.length < end + 4 + length) return;
      const message = JSON.parse(buffer.toString('utf8', end + 4, end + 4 + length));
      buffer = buffer.subarray(end + 4 + length);
      if (message.id !== undefined && replies.has(message.id)) {
        replies.get(message.id)(message);
        replies.delete(message.id);
      } else if (message.method === 'textDocument/publishDiagnostics') {
        published.set(message.params.uri, message.params.diagnostics);
        for (const w of waiting.splice(0)) {
          if (w.uri === message.params.uri) w.resolve(message.params.diagnostics);
          else waiting.push(w);
        }
      }
    }
  });
  const send = (message) => {
    const body = Buffer.from(JSON.stringify({jsonrpc: '2.0', ...message}));
    server.stdin.write(`Content-Length: ${body.length}\r\n\r\n`);
    server.stdin.write(body);
  };
  const request = (method, params) => new Promise((resolve, reject) => {
    const id = ++nextId;
    replies.set(id, (m) => (m.error ? reject(new Error(`${method}: ${m.error.message}`)) : resolve(m.result)));
    send({id, method, params});
  });
  await request('initialize', {processId: process.pid, rootUri: null, capabilities: {}});
  send({method: 'initialized', params: {}});
  let version = 0;
  return {
    request,
    /// Opens (or replaces) `uri` with `text`; resolves with its published diagnostics.
    open(uri, text) {
      published.delete(uri);
      const result = new Promise((resolve) => waiting.push({uri, resolve}));
      if (version === 0) {
        send({method: 'textDocument/didOpen', params: {textDocument: {uri, languageId: 'f2', version: ++version, text}}});
      } else {
        send({method: 'textDocument/didChange',
              params: {textDocument: {uri, version: ++version}, contentChanges: [{text}]}});
      }
      return result;
    },
    async close() {
      await request('shutdown', null);
      send({method: 'exit'});
      server.stdin.end();
    },
  };
}

module.exports = {startLsp};
