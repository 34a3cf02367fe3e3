// Tokenizes the sample scenes with the extension's TextMate grammar, through
// the same engine as VS Code (vscode-textmate + vscode-oniguruma), and checks
// the scopes listed in expectations.json; then checks that the files the
// manifest names exist and parse.   node test/grammar_test.js
"use strict";
const fs = require("fs");
const path = require("path");
const vm = require("vm");
const vsctm = require("vscode-textmate");
const oniguruma = require("vscode-oniguruma");

const root = path.join(__dirname, "..");
const grammarPath = path.join(root, "syntaxes", "f2.tmLanguage.json");
const wasm = fs.readFileSync(path.join(path.dirname(require.resolve("vscode-oniguruma")), "onig.wasm"));

async function main() {
  await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
  const registry = new vsctm.Registry({
    onigLib: Promise.resolve({
      createOnigScanner: (patterns) => new oniguruma.OnigScanner(patterns),
      createOnigString: (s) => new oniguruma.OnigString(s),
    }),
    loadGrammar: async (scopeName) =>
      scopeName === "source.f2"
        ? vsctm.parseRawGrammar(fs.readFileSync(grammarPath, "utf8"), grammarPath)
        : null,
  });
  const grammar = await registry.loadGrammar("source.f2");
  const expectations = JSON.parse(fs.readFileSync(path.join(__dirname, "expectations.json"), "utf8"));
  let failures = 0, checks = 0;
  for (const [sample, list] of Object.entries(expectations)) {
    if (sample === "comment") continue;
    const lines = fs.readFileSync(path.join(__dirname, "samples", sample), "utf8").split("\n");
    const tokens = [];
    let state = vsctm.INITIAL;
    for (const line of lines) {
      const r = grammar.tokenizeLine(line, state);
      tokens.push(r.tokens.map((t) => ({ text: line.substring(t.startIndex, t.endIndex), scopes: t.scopes })));
      state = r.ruleStack;
    }
    for (const [line, text, occurrence, scope] of list) {
      checks++;
      const matching = (tokens[line] || []).filter((t) => t.text === text);
      const token = matching[occurrence];
      if (!token || !token.scopes.includes(scope)) {
        failures++;
        const seen = (tokens[line] || []).map((t) => `${JSON.stringify(t.text)} ${t.scopes.slice(1).join(" ")}`);
        console.log(`FAIL ${sample}:${line + 1}: ${JSON.stringify(text)} should have ${scope}\n  line tokens:\n    ${seen.join("\n    ")}`);
      }
    }
  }
  console.log(`${checks - failures}/${checks} scope checks passed`);
  failures += checkManifest();
  process.exit(failures === 0 ? 0 : 1);
}

/** The files package.json names exist and parse; the extension's code compiles. */
function checkManifest() {
  const manifest = JSON.parse(fs.readFileSync(path.join(root, "package.json"), "utf8"));
  const c = manifest.contributes;
  const files = [
    ...c.languages.map((l) => l.configuration),
    ...c.grammars.map((g) => g.path),
    ...c.snippets.map((s) => s.path),
  ];
  let problems = 0;
  for (const f of files) {
    try {
      JSON.parse(fs.readFileSync(path.join(root, f), "utf8"));
    } catch (e) {
      problems++;
      console.log(`FAIL package.json names ${f}: ${e.message}`);
    }
  }
  try {
    new vm.Script(fs.readFileSync(path.join(root, manifest.main), "utf8"), { filename: manifest.main });
  } catch (e) {
    problems++;
    console.log(`FAIL ${manifest.main} does not compile: ${e.message}`);
  }
  console.log(`manifest: ${files.length} contributed files and ${manifest.main} checked`);
  return problems;
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
