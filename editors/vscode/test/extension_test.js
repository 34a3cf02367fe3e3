// Loads extension.js with stand-ins for the `vscode` API and the language
// client (no editor needed) and checks what activate() sets up: a client that
// runs `f2 lsp` for f2 documents, the two commands, formatting only when
// f2.formatKeys is on, the frame offered by "Render this frame", and that
// package.json declares what the code uses.
//   node test/extension_test.js
"use strict";
const Module = require("module");
const path = require("path");
const assert = require("assert");

const settings = { path: "/opt/f2/bin/f2", viewerPath: "f2-viewer", formatKeys: false };
const registered = {};
let client;
let offeredFrame;
const editor = {
  document: {
    languageId: "f2",
    isUntitled: false,
    save: async () => true,
    uri: { fsPath: "/scenes/a.f2" },
    lineAt: () => ({ text: "  /key 36 f2.head 0 0 0 -5 55 0" }),
  },
  selection: { active: { line: 4 } },
};
const vscode = {
  workspace: { getConfiguration: (section) => ({ get: (name) => (section === "f2" ? settings[name] : undefined) }) },
  window: {
    activeTextEditor: editor,
    showErrorMessage: (m) => assert.fail(`unexpected error message: ${m}`),
    showInputBox: async (options) => {
      offeredFrame = options.value;
      return undefined; // cancelled: nothing is rendered
    },
  },
  commands: { registerCommand: (name, fn) => ((registered[name] = fn), { dispose() {} }) },
  Uri: { file: (p) => ({ fsPath: p }) },
  ViewColumn: { Beside: -2 },
};
class LanguageClient {
  constructor(id, name, serverOptions, clientOptions) {
    client = { id, name, serverOptions, clientOptions, started: false };
  }
  start() {
    client.started = true;
    return Promise.resolve();
  }
  stop() {
    return Promise.resolve();
  }
}
const load = Module._load;
Module._load = function (request, parent, isMain) {
  if (request === "vscode") return vscode;
  if (request === "vscode-languageclient/node") return { LanguageClient };
  return load.call(this, request, parent, isMain);
};

(async () => {
  const extension = require(path.join(__dirname, "..", "extension.js"));
  const context = { subscriptions: [] };
  await extension.activate(context);
  assert.deepStrictEqual(client.serverOptions.run, { command: "/opt/f2/bin/f2", args: ["lsp"] });
  assert.deepStrictEqual(client.clientOptions.documentSelector, [{ language: "f2" }]);
  assert.ok(client.started, "the client is started");
  assert.deepStrictEqual(Object.keys(registered).sort(), ["f2.openInViewer", "f2.renderFrame"]);
  assert.strictEqual(context.subscriptions.length, 2);

  const format = client.clientOptions.middleware.provideDocumentFormattingEdits;
  const next = () => ["edit"];
  assert.deepStrictEqual(format({}, {}, {}, next), [], "formatting is off by default");
  settings.formatKeys = true;
  assert.deepStrictEqual(format({}, {}, {}, next), ["edit"], "formatting when f2.formatKeys is on");

  await registered["f2.renderFrame"]();
  assert.strictEqual(offeredFrame, "36", "on a /key line the key's frame is offered");

  // The manifest agrees with the code: VS Code activates the extension for f2
  // documents from contributes.languages alone (VS Code 1.74 and later), the
  // commands it registers are the ones it declares, the settings it reads exist.
  const manifest = require(path.join(__dirname, "..", "package.json"));
  assert.deepStrictEqual(manifest.activationEvents, []);
  const [major, minor] = /^\^(\d+)\.(\d+)/.exec(manifest.engines.vscode).slice(1).map(Number);
  assert.ok(major > 1 || minor >= 74, "implicit activation needs VS Code 1.74");
  assert.deepStrictEqual(manifest.contributes.languages.map((l) => l.id), ["f2"]);
  assert.deepStrictEqual(manifest.contributes.commands.map((c) => c.command).sort(), Object.keys(registered).sort());
  for (const name of ["path", "viewerPath", "formatKeys"]) {
    assert.strictEqual(manifest.contributes.configuration.properties[`f2.${name}`].default, name === "formatKeys" ? false : name === "path" ? "f2" : "f2-viewer");
  }
  assert.ok(manifest.devDependencies["@vscode/vsce"], "the packager comes from npm ci (lsp.vscode_package)");
  console.log("extension: client, commands, formatting switch, offered frame and manifest checked");
})().catch((e) => {
  console.error(e);
  process.exit(1);
});
