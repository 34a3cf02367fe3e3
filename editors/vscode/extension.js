// The F2 Stage extension: starts `f2 lsp` for .f2 files, and adds the commands
// "F2: Open in viewer" and "F2: Render this frame".
"use strict";
const vscode = require("vscode");
const path = require("path");
const { spawn } = require("child_process");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function setting(name) {
  return vscode.workspace.getConfiguration("f2").get(name);
}

/** The .f2 document of the active editor, saved; undefined (with a message) otherwise. */
async function activeScene() {
  const editor = vscode.window.activeTextEditor;
  if (!editor || editor.document.languageId !== "f2") {
    vscode.window.showErrorMessage("F2: open a .f2 scene first.");
    return undefined;
  }
  if (editor.document.isUntitled || !(await editor.document.save())) {
    vscode.window.showErrorMessage("F2: save the scene to a file first.");
    return undefined;
  }
  return editor.document.uri.fsPath;
}

async function openInViewer() {
  const scene = await activeScene();
  if (!scene) return;
  const viewer = spawn(setting("viewerPath"), [scene], { detached: true, stdio: "ignore" });
  viewer.on("error", (e) => vscode.window.showErrorMessage(`F2: cannot start ${setting("viewerPath")}: ${e.message}`));
  viewer.unref();
}

async function renderFrame() {
  const scene = await activeScene();
  if (!scene) return;
  // On a /key line, "this frame" is that key's frame.
  const editor = vscode.window.activeTextEditor;
  const key = /^\s*\/key\s+(\d+(?:\.\d+)?)(?=\s|$)/.exec(editor.document.lineAt(editor.selection.active.line).text);
  const frame = await vscode.window.showInputBox({
    prompt: "Frame to render",
    value: key ? key[1] : "0",
    validateInput: (v) => (/^\d+(\.\d+)?$/.test(v.trim()) ? undefined : "a frame number, such as 0 or 120"),
  });
  if (frame === undefined) return;
  const out = path.join(path.dirname(scene), `${path.basename(scene, ".f2")}_${frame.trim()}.png`);
  const args = ["render", scene, "--frame", frame.trim(), "-o", out];
  let errors = "";
  const render = spawn(setting("path"), args);
  render.stderr.on("data", (d) => (errors += d));
  render.on("error", (e) => vscode.window.showErrorMessage(`F2: cannot start ${setting("path")}: ${e.message}`));
  render.on("close", (code) => {
    if (code === 0) {
      vscode.commands.executeCommand("vscode.open", vscode.Uri.file(out), { viewColumn: vscode.ViewColumn.Beside });
    } else {
      vscode.window.showErrorMessage(`F2: f2 render failed: ${errors.trim() || "exit " + code}`);
    }
  });
}

function activate(context) {
  const server = { command: setting("path"), args: ["lsp"] };
  client = new LanguageClient("f2", "F2 Stage", { run: server, debug: server }, {
    documentSelector: [{ language: "f2" }],
    middleware: {
      // Aligning /key lines is offered only when the user turns it on.
      provideDocumentFormattingEdits: (document, options, token, next) =>
        setting("formatKeys") ? next(document, options, token) : [],
    },
  });
  context.subscriptions.push(
    vscode.commands.registerCommand("f2.openInViewer", openInViewer),
    vscode.commands.registerCommand("f2.renderFrame", renderFrame),
  );
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
