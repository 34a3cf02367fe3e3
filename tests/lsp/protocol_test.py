#!/usr/bin/env python3
"""Drives `f2 lsp` through a whole editing session and compares every reply
with the exact JSON expected: initialize, didOpen with errors, didChange that
fixes them, completion after `r1.`, hover, definition, references, rename,
then malformed input, shutdown and exit.

    protocol_test.py PATH/TO/f2
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lsp_client import Client  # noqa: E402

URI = "file:///scenes/story%20one.f2"
PATH = "/scenes/story one.f2"
failures = []


def expect(what, got, want):
    if got != want:
        failures.append("%s:\n  got  %r\n  want %r" % (what, got, want))


def position(line, character):
    return {"line": line, "character": character}


def rng(line, start, end):
    return {"start": position(line, start), "end": position(line, end)}


def doc_params(line, character, **extra):
    return dict({"textDocument": {"uri": URI}, "position": position(line, character)}, **extra)


BROKEN = "\n".join([
    "/camera 320 240 0.5",
    "/amb_light 0.3",
    "/robot r1 0 0 200 0 180 0",
    "/human h1 300 0 150 0 90 0  # приве́т",
    "/paint h1 \U0001F600 300 0",     # a 4-byte character: 2 UTF-16 units
    "/key 0 r1.lhnd",
    "/key 5 r1 0 0 200 0 135 0",
    "/paint r1.head 196 204 222",
    ""])
FIXED = BROKEN.replace("/paint h1 \U0001F600 300 0", "/paint h1 30 60 90  # \U0001F600").replace(
    "r1.lhnd", "r1.lhand")

CAPABILITIES = {
    "positionEncoding": "utf-16",
    "textDocumentSync": {"openClose": True, "change": 1, "save": {"includeText": False}},
    "completionProvider": {"triggerCharacters": [".", "/"]},
    "hoverProvider": True,
    "definitionProvider": True,
    "referencesProvider": True,
    "renameProvider": {"prepareProvider": True},
    "documentSymbolProvider": True,
    "foldingRangeProvider": True,
    "documentFormattingProvider": True,
}


def main():
    client = Client([sys.argv[1], "lsp"])

    # Before initialize a request is refused.
    reply = client.request("textDocument/hover", doc_params(0, 0))
    expect("request before initialize", reply.get("error", {}).get("code"), -32002)

    reply = client.request("initialize", {"processId": None, "rootUri": None, "capabilities": {}})
    expect("initialize", reply["result"],
           {"capabilities": CAPABILITIES, "serverInfo": {"name": "f2 lsp", "version": "0.1.0"}})
    client.notify("initialized", {})

    # didOpen with three errors: exact ranges in UTF-16 units.
    client.notify("textDocument/didOpen",
                  {"textDocument": {"uri": URI, "languageId": "f2", "version": 1, "text": BROKEN}})
    published = client.next_notification("textDocument/publishDiagnostics")["params"]
    expect("diagnostics of the broken scene", published, {
        "uri": URI, "version": 1, "diagnostics": [
            {"range": rng(4, 10, 12), "severity": 1, "source": "f2",
             "message": "expected a number, got '\U0001F600' (it contains U+1F600 at column 11, "
                        "but commands, names and numbers are plain ASCII)"},
            {"range": rng(4, 13, 16), "severity": 1, "source": "f2",
             "message": "green must be a whole number from 0 to 255, got 300"},
            {"range": rng(5, 10, 14), "severity": 1, "source": "f2",
             "message": "unknown part 'lhnd' (did you mean 'lhand'?)"},
        ]})

    # didChange (whole text) fixes them.
    client.notify("textDocument/didChange", {"textDocument": {"uri": URI, "version": 2},
                                             "contentChanges": [{"text": FIXED}]})
    published = client.next_notification("textDocument/publishDiagnostics")["params"]
    expect("diagnostics after the fix", published, {"uri": URI, "version": 2, "diagnostics": []})

    # Completion after `r1.` (line 5 is "/key 0 r1.lhand"): the robot's parts.
    reply = client.request("textDocument/completion", doc_params(5, 10))
    expect("completion after r1.", reply["result"], [
        {"label": "r1." + part, "kind": 5, "detail": "part of robot r1",
         "textEdit": {"range": rng(5, 7, 10), "newText": "r1." + part}}
        for part in ("body", "head", "lhand", "rhand")])

    # Hover on a name (line 6 is "/key 5 r1 0 0 200 0 135 0").
    reply = client.request("textDocument/hover", doc_params(6, 8))
    expect("hover on r1", reply["result"], {
        "range": rng(6, 7, 9),
        "contents": {"kind": "markdown", "value":
                     "**robot** `r1`, created at line 3:\n"
                     "```f2\n/robot r1 0 0 200 0 180 0\n```\n"
                     "- keys: 1 (own), body 0, head 0, lhand 1, rhand 0\n"
                     "- parts: body, head, lhand, rhand\n"
                     "- at frame 0: position (0, 0, 200), rotation (0, 135, 0)\n"}})

    # Definition from a use in `r1.head` (line 7).
    reply = client.request("textDocument/definition", doc_params(7, 8))
    expect("definition of r1", reply["result"], {"uri": URI, "range": rng(2, 7, 9)})

    reply = client.request("textDocument/references", doc_params(7, 8, context={"includeDeclaration": True}))
    expect("references of r1", reply["result"],
           [{"uri": URI, "range": rng(line, 7, 9)} for line in (2, 5, 6, 7)])

    # Rename r1 -> f2 everywhere; bad names are refused.
    reply = client.request("textDocument/prepareRename", doc_params(5, 8))
    expect("prepareRename", reply["result"], {"range": rng(5, 7, 9), "placeholder": "r1"})
    reply = client.request("textDocument/rename", doc_params(5, 8, newName="f2"))
    expect("rename r1 -> f2", reply["result"], {"changes": {URI: [
        {"range": rng(line, 7, 9), "newText": "f2"} for line in (2, 5, 6, 7)]}})
    reply = client.request("textDocument/rename", doc_params(5, 8, newName="2x"))
    expect("rename to an invalid name", reply.get("error", {}).get("code"), -32602)
    reply = client.request("textDocument/rename", doc_params(5, 8, newName="h1"))
    expect("rename to an existing name", reply.get("error", {}).get("code"), -32803)

    # Whatever a client sends, an answer and no crash.
    body = b"{not json"
    client.send_raw(b"Content-Length: %d\r\n\r\n" % len(body) + body)
    reply = client.read()
    expect("malformed JSON", (reply.get("id"), reply.get("error", {}).get("code")), (None, -32700))
    reply = client.request("textDocument/frobnicate", {})
    expect("unknown method", reply.get("error", {}).get("code"), -32601)
    reply = client.request("textDocument/hover", doc_params(9999, 5))
    expect("hover past the end", reply.get("result", "missing"), None)
    reply = client.request("textDocument/completion", doc_params(2, 100000))
    expect("completion past the end of a line", reply.get("result"), [])
    reply = client.request("textDocument/hover", doc_params(1.5, 2))
    expect("a fractional line", reply.get("error", {}).get("code"), -32602)

    reply = client.request("shutdown")
    expect("shutdown", ("result" in reply, reply.get("result")), (True, None))
    client.notify("exit", None)
    expect("exit code", client.close(), 0)

    if failures:
        print("\n".join(failures))
        print("FAILED: %d check(s)" % len(failures))
        return 1
    print("ok: the whole session matched")
    return 0


if __name__ == "__main__":
    sys.exit(main())
