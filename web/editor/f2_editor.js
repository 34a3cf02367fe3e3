// The page's scene editor: CodeMirror 6, bundled by esbuild (scripts/web.sh)
// into editor.js, which defines window.F2Editor. Its highlighting reads the
// word lists the TextMate grammar is generated from (the module's
// "f2/languageLists", src/lsp/language_files.cpp), its completion and hover
// ask the module's language server features, and its squiggles are the
// module's diagnostics (`f2 check`'s, with the language server's marked range).
import {autocompletion} from '@codemirror/autocomplete';
import {defaultKeymap, history, historyKeymap, indentWithTab} from '@codemirror/commands';
import {HighlightStyle, StreamLanguage, syntaxHighlighting} from '@codemirror/language';
import {forEachDiagnostic, lintGutter, setDiagnostics} from '@codemirror/lint';
import {EditorState} from '@codemirror/state';
import {EditorView, hoverTooltip, keymap, lineNumbers, highlightActiveLine} from '@codemirror/view';
import {tags} from '@lezer/highlight';

/// A tokenizer for CodeMirror's StreamLanguage from the language's word lists,
/// the same classes as the TextMate grammar (editors/vscode/syntaxes).
function f2Language(lists) {
  const set = (...names) => new Set(names.flatMap((name) => lists[name] || []));
  const creating = set('creating', 'variable-commands', 'path-commands');
  const commands = set('commands');
  const modes = set('modes');
  const options = set('light-options', 'material-options', 'attach-words', 'key-properties', 'drive-channels');
  const functions = set('functions');
  const constants = set('constants', 'drive-inputs');
  const parts = set('parts');
  const camera = set('camera');
  return StreamLanguage.define({
    name: 'f2',
    startState: () => ({depth: 0}),
    token(stream, state) {
      if (stream.sol()) state.depth = 0;
      if (stream.eatSpace()) return null;
      if (stream.peek() === '#') {
        stream.skipToEnd();
        return 'comment';
      }
      if (stream.peek() === '"') {
        stream.next();
        while (!stream.eol()) {
          const c = stream.next();
          if (c === '\\') stream.next();
          else if (c === '"') break;
        }
        return 'string';
      }
      if (state.depth === 0 && stream.match(/^\/[^ \t#]*/)) {
        const word = stream.current().slice(1);
        if (!commands.has(word)) return 'invalid';
        return creating.has(word) ? 'definitionKeyword' : 'keyword';
      }
      if (stream.eat('{') || stream.eat('(')) {
        ++state.depth;
        return 'brace';
      }
      if (stream.eat('}') || stream.eat(')')) {
        state.depth = Math.max(0, state.depth - 1);
        return 'brace';
      }
      if (stream.match(/^[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?s?/)) return 'number';
      if (stream.match(/^[A-Za-z_][A-Za-z0-9_]*/)) {
        const word = stream.current();
        if (state.depth > 0) {
          if (functions.has(word)) return 'function';
          return constants.has(word) ? 'constant' : 'variable';
        }
        if (modes.has(word)) return 'modifier';
        if (camera.has(word)) return 'self';
        if (options.has(word)) return 'propertyName';
        if (parts.has(word) && stream.string[stream.start - 1] === '.') return 'propertyName';
        return 'name';
      }
      if (stream.match(/^(==|!=|<=|>=|&&|\|\||[-+*/%^<>!.,=&|])/)) return 'operator';
      stream.next();
      return null;
    },
    tokenTable: {
      definitionKeyword: tags.definitionKeyword, keyword: tags.keyword, invalid: tags.invalid,
      function: tags.function(tags.variableName), constant: tags.constant(tags.variableName),
      variable: tags.variableName, modifier: tags.atom, self: tags.self, propertyName: tags.propertyName,
      name: tags.name, brace: tags.brace,
    },
  });
}

const highlighting = HighlightStyle.define([
  {tag: tags.comment, color: '#6a9955', fontStyle: 'italic'},
  {tag: tags.string, color: '#ce9178'},
  {tag: tags.keyword, color: '#569cd6'},
  {tag: tags.definitionKeyword, color: '#c586c0'},
  {tag: tags.invalid, color: '#f44747', textDecoration: 'underline wavy'},
  {tag: tags.number, color: '#b5cea8'},
  {tag: tags.atom, color: '#4ec9b0'},
  {tag: tags.self, color: '#9cdcfe', fontWeight: 'bold'},
  {tag: tags.propertyName, color: '#9cdcfe'},
  {tag: tags.function(tags.variableName), color: '#dcdcaa'},
  {tag: tags.constant(tags.variableName), color: '#4fc1ff'},
  {tag: tags.variableName, color: '#d7ba7d'},
  {tag: tags.name, color: '#e6e6e6'},
  {tag: tags.operator, color: '#d4d4d4'},
  {tag: tags.brace, color: '#ffd700'},
]);

const theme = EditorView.theme({
  '&': {backgroundColor: '#111', color: '#e6e6e6', height: '100%'},
  '.cm-content': {fontFamily: 'ui-monospace, monospace', fontSize: '13px', caretColor: '#fff'},
  '.cm-gutters': {backgroundColor: '#1a1a1a', color: '#777', border: 'none'},
  '.cm-activeLine': {backgroundColor: '#ffffff0a'},
  '&.cm-focused .cm-cursor': {borderLeftColor: '#fff'},
  '.cm-tooltip': {backgroundColor: '#252526', color: '#ddd', border: '1px solid #454545', maxWidth: '36em'},
  '.cm-f2-hover': {padding: '4px 8px', whiteSpace: 'pre-wrap'},
  '.cm-f2-hover code, .cm-completionInfo code': {fontFamily: 'ui-monospace, monospace', color: '#9cdcfe'},
  '.cm-completionInfo': {whiteSpace: 'pre-wrap', maxWidth: '36em'},
}, {dark: true});

/// UTF-16 code units (JavaScript string length) of the first `bytes` UTF-8 bytes of `line`.
function utf16Column(line, bytes) {
  let units = 0;
  for (const c of line) {
    if (bytes <= 0) break;
    const code = c.codePointAt(0);
    bytes -= code < 0x80 ? 1 : code < 0x800 ? 2 : code < 0x10000 ? 3 : 4;
    units += c.length;
  }
  return units;
}

/// A little of the language server's markdown as DOM: ```f2 blocks, `code`, **bold**.
function markdownNode(text) {
  const node = document.createElement('div');
  for (const [i, block] of text.split(/```(?:f2)?\n?/).entries()) {
    if (i % 2 === 1) {
      const code = document.createElement('code');
      code.textContent = block.replace(/\n$/, '');
      code.style.display = 'block';
      node.append(code);
      continue;
    }
    for (const [j, piece] of block.split(/(`[^`]*`|\*\*[^*]*\*\*)/).entries()) {
      if (j % 2 === 0) {
        node.append(piece);
      } else if (piece.startsWith('`')) {
        const code = document.createElement('code');
        code.textContent = piece.slice(1, -1);
        node.append(code);
      } else {
        const bold = document.createElement('b');
        bold.textContent = piece.slice(2, -2);
        node.append(bold);
      }
    }
  }
  return node;
}

const kCompletionTypes = {14: 'keyword', 15: 'keyword', 6: 'variable', 5: 'property', 20: 'enum', 17: 'text',
                          3: 'function', 7: 'class', 10: 'property'};

/// The editor in `parent`. options: {text, lists (f2/languageLists), lsp(method, params) → Promise,
/// onChange(text)}.
function create(parent, {text, lists, lsp, onChange}) {
  const position = (doc, offset) => {
    const line = doc.lineAt(offset);
    return {line: line.number - 1, character: offset - line.from};
  };
  const offset = (doc, p) => {
    const line = doc.line(Math.min(p.line + 1, doc.lines));
    return Math.min(line.from + p.character, line.to);
  };
  // Each request first hands the module the current text ("open"), so the
  // analysis is of what the editor shows.
  const ask = (doc, method, params) => lsp('open', {text: doc.toString()}).then(() => lsp(method, params));

  async function complete(context) {
    // Typing opens the list on a command or a name, not on a number.
    const word = context.matchBefore(/[\/A-Za-z_][\/A-Za-z0-9_.]*/);
    if (!context.explicit && !word) return null;
    let items = await ask(context.state.doc, 'textDocument/completion',
                            {position: position(context.state.doc, context.pos)});
    // Files (after /include) would be the module's empty virtual file system: the page has one text.
    const kFile = 17;
    items = Array.isArray(items) ? items.filter((item) => item.kind !== kFile) : [];
    if (!items.length) return null;
    // The server's edit range says where the word it completes begins (after a '.' in name.part).
    const edit = items[0].textEdit;
    const from = edit && edit.range ? offset(context.state.doc, edit.range.start) : word ? word.from : context.pos;
    return {
      from,
      options: items.map((item) => {
        const edit = item.textEdit;
        const insert = edit ? edit.newText : item.insertText || item.label;
        const documentation = item.documentation && (item.documentation.value || item.documentation);
        return {
          label: item.label,
          detail: item.detail,
          type: kCompletionTypes[item.kind],
          // Snippet placeholders (${1:name}) as their names: CodeMirror's snippets are another syntax.
          apply: insert.replace(/\$\{\d+:([^}]*)\}/g, '$1').replace(/\$\d+/g, ''),
          info: documentation ? () => markdownNode(documentation) : undefined,
        };
      }),
      validFor: /^[\/A-Za-z0-9_.]*$/,
    };
  }

  const hover = hoverTooltip(async (view, pos) => {
    const result = await ask(view.state.doc, 'textDocument/hover', {position: position(view.state.doc, pos)});
    if (!result || !result.contents) return null;
    const range = result.range;
    return {
      pos: range ? offset(view.state.doc, range.start) : pos,
      end: range ? offset(view.state.doc, range.end) : pos,
      create: () => {
        const dom = markdownNode(result.contents.value || String(result.contents));
        dom.className = 'cm-f2-hover';
        return {dom};
      },
    };
  }, {hoverTime: 300});

  const view = new EditorView({
    parent,
    state: EditorState.create({
      doc: text,
      extensions: [
        lineNumbers(), highlightActiveLine(), history(), keymap.of([...defaultKeymap, ...historyKeymap, indentWithTab]),
        f2Language(lists), syntaxHighlighting(highlighting), theme, autocompletion({override: [complete]}), hover,
        lintGutter(), EditorView.contentAttributes.of({'aria-label': 'scene text'}),
        EditorView.updateListener.of((update) => {
          if (update.docChanged) onChange(update.state.doc.toString());
        }),
      ],
    }),
  });

  return {
    view,
    text: () => view.state.doc.toString(),
    /// Replaces the whole text (an example, a share link).
    setText(newText) {
      view.dispatch({changes: {from: 0, to: view.state.doc.length, insert: newText}});
    },
    /// The module's diagnostics (1-based line, byte columns [markColumn, endColumn)) as squiggles.
    setDiagnostics(diagnostics) {
      const doc = view.state.doc;
      const marks = diagnostics.map((d) => {
        const line = doc.line(Math.max(1, Math.min(d.line, doc.lines)));
        const own = d.file === 'scene.f2' && d.line <= doc.lines;
        const from = own ? line.from + utf16Column(line.text, d.markColumn - 1) : line.from;
        const to = own ? line.from + utf16Column(line.text, d.endColumn - 1) : line.to;
        return {from, to, severity: d.severity, message: `${d.line}:${d.column}: ${d.message}`};
      });
      view.dispatch(setDiagnostics(view.state, marks));
    },
    /// The squiggles the editor holds: 1-based line, [column, endColumn) in
    /// UTF-16 units (as the language server's 0-based characters + 1), message.
    squiggles() {
      const doc = view.state.doc;
      const out = [];
      forEachDiagnostic(view.state, (d, from, to) => {
        const line = doc.lineAt(from);
        out.push({line: line.number, column: from - line.from + 1, endLine: doc.lineAt(to).number,
                  endColumn: to - doc.lineAt(to).from + 1, severity: d.severity, message: d.message});
      });
      return out;
    },
  };
}

// scrollTo: an effect that scrolls a position into view (the page test hovers there).
window.F2Editor = {create, scrollTo: (pos) => EditorView.scrollIntoView(pos, {y: 'center'})};
