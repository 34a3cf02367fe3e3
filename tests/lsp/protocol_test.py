#!/usr/bin/env python3
"""Drives `f2 lsp` through a whole editing session and compares every reply
with the exact JSON expected: initialize, didOpen with errors, didChange that
fixes them, completion after `r1.`, hover, definition, references, rename,
then malformed input, shutdown and exit; and a second session on a scene
with an included file (definition, references, rename, hover and errors
across the include, both ways).

    protocol_test.py PATH/TO/f2
"""
import os
import shutil
import sys
import tempfile
import urllib.parse

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


MAIN = "\n".join([
    "/let w 40",
    '/include "parts/stage.f2"',
    "/sphere ball (w) 0 (h) 0",
    "/key 0 prop",
    "/key 10 prop 0 (h * 2) 0 0 0 0",
    "/look_at prop",
    "/key 0 camera",
    ""])
STAGE = "\n".join([
    "/amb_light 1",
    "/let h 25",
    "/box prop 10 (w) 10 0 0 0",
    "/camera 320 240 0.5 0 100 -500",
    ""])


def included_session(f2):
    """Variables and objects followed into an included file and back, the
    camera's hover, and an include's errors on the include line."""
    directory = tempfile.mkdtemp(prefix="f2 lsp ")
    try:
        os.mkdir(os.path.join(directory, "parts"))
        main_path = os.path.join(directory, "main.f2")
        stage_path = os.path.join(directory, "parts", "stage.f2")
        for path, text in ((main_path, MAIN), (stage_path, STAGE)):
            with open(path, "w") as f:
                f.write(text)
        main_uri = "file://" + urllib.parse.quote(main_path)
        stage_uri = "file://" + urllib.parse.quote(stage_path)

        def at(uri, line, character, **extra):
            return dict({"textDocument": {"uri": uri}, "position": position(line, character)}, **extra)

        def loc(uri, line, start, end):
            return {"uri": uri, "range": rng(line, start, end)}

        client = Client([f2, "lsp"])
        client.request("initialize", {"processId": None, "rootUri": None, "capabilities": {}})
        client.notify("textDocument/didOpen",
                      {"textDocument": {"uri": main_uri, "languageId": "f2", "version": 1, "text": MAIN}})
        expect("included: diagnostics of main.f2", client.next_notification("textDocument/publishDiagnostics")["params"],
               {"uri": main_uri, "version": 1, "diagnostics": []})

        # From main.f2 into parts/stage.f2 (read from disk: it is not open).
        reply = client.request("textDocument/definition", at(main_uri, 2, 20))
        expect("included: definition of h", reply["result"], loc(stage_uri, 1, 5, 6))
        reply = client.request("textDocument/definition", at(main_uri, 3, 8))
        expect("included: definition of prop", reply["result"], loc(stage_uri, 2, 5, 9))
        reply = client.request("textDocument/references", at(main_uri, 2, 20, context={"includeDeclaration": True}))
        expect("included: references of h", reply["result"],
               [loc(stage_uri, 1, 5, 6), loc(main_uri, 2, 20, 21), loc(main_uri, 4, 16, 17)])
        reply = client.request("textDocument/rename", at(main_uri, 3, 8, newName="crate"))
        expect("included: rename prop -> crate", reply["result"], {"changes": {
            main_uri: [{"range": rng(3, 7, 11), "newText": "crate"}, {"range": rng(4, 8, 12), "newText": "crate"},
                       {"range": rng(5, 9, 13), "newText": "crate"}],
            stage_uri: [{"range": rng(2, 5, 9), "newText": "crate"}]}})
        reply = client.request("textDocument/rename", at(main_uri, 4, 16, newName="height"))
        expect("included: rename h -> height", reply["result"], {"changes": {
            main_uri: [{"range": rng(2, 20, 21), "newText": "height"}, {"range": rng(4, 16, 17), "newText": "height"}],
            stage_uri: [{"range": rng(1, 5, 6), "newText": "height"}]}})
        for what, params, message in [
                ("camera", at(main_uri, 3, 8, newName="camera"),
                 "'camera' names the scene camera and cannot be an object's name"),
                ("a taken object name", at(main_uri, 3, 8, newName="ball"), "an object named 'ball' already exists"),
                ("a taken variable name", at(main_uri, 4, 16, newName="w"), "a variable named 'w' already exists"),
                ("pi", at(main_uri, 4, 16, newName="pi"), "'pi' is predefined and cannot be a variable")]:
            reply = client.request("textDocument/rename", params)
            expect("included: rename to " + what, reply.get("error"), {"code": -32803, "message": message})

        reply = client.request("textDocument/hover", at(main_uri, 6, 9))
        expect("included: hover on camera", reply["result"], {
            "range": rng(6, 7, 13),
            "contents": {"kind": "markdown", "value":
                         "**camera**, the scene camera, set at line 4 of %s:\n"
                         "```f2\n/camera 320 240 0.5 0 100 -500\n```\n"
                         "- image 320 \u00d7 240, d 0.5\n- keys: 1\n- looks at: `prop` (line 6)\n"
                         "- rides on: nothing\n"
                         "- at frame 0: eye (0, 100, -500), looking along (0, -0.196116, 0.980581)\n" % stage_path}})
        reply = client.request("textDocument/hover", at(main_uri, 2, 20))
        expect("included: hover on h", reply["result"], {
            "range": rng(2, 20, 21),
            "contents": {"kind": "markdown", "value":
                         "**variable** `h` = 25, defined at line 2 of %s:\n```f2\n/let h 25\n```" % stage_path}})
        reply = client.request("textDocument/completion", at(main_uri, 4, 16))
        expect("included: variables offered in an expression", [i["label"] for i in reply["result"][:3]],
               ["w", "h", "pi"])
        expect("included: where h comes from", reply["result"][1]["detail"], "variable, line 2 of stage.f2")
        reply = client.request("textDocument/completion", at(main_uri, 1, 16))
        expect("included: include path completion", reply["result"],
               [{"label": "stage.f2", "kind": 17, "detail": "scene file",
                 "textEdit": {"range": rng(1, 16, 16), "newText": "stage.f2"}}])

        # And back: stage.f2 opened is read as part of main.f2 (w is known there).
        client.notify("textDocument/didOpen",
                      {"textDocument": {"uri": stage_uri, "languageId": "f2", "version": 1, "text": STAGE}})
        expect("included: diagnostics of stage.f2 opened",
               client.next_notification("textDocument/publishDiagnostics")["params"],
               {"uri": stage_uri, "version": 1, "diagnostics": []})
        reply = client.request("textDocument/definition", at(stage_uri, 2, 14))
        expect("included: definition of w from stage.f2", reply["result"], loc(main_uri, 0, 5, 6))
        reply = client.request("textDocument/references", at(stage_uri, 2, 6, context={"includeDeclaration": False}))
        expect("included: references of prop from stage.f2", reply["result"],
               [loc(main_uri, 3, 7, 11), loc(main_uri, 4, 8, 12), loc(main_uri, 5, 9, 13)])

        # An error typed into stage.f2 (not saved): on its own URI, and on main.f2's include line.
        del client.notifications[:]
        client.notify("textDocument/didChange", {"textDocument": {"uri": stage_uri, "version": 2},
                                                 "contentChanges": [{"text": STAGE.replace("10 0 0 0", "10 0 0 zz")}]})
        published = {}
        while len(published) < 2:
            params = client.next_notification("textDocument/publishDiagnostics")["params"]
            published[params["uri"]] = params
        error = {"range": rng(2, 24, 26), "severity": 1, "source": "f2", "message": "expected a number, got 'zz'"}
        expect("included: the error in stage.f2", published[stage_uri],
               {"uri": stage_uri, "version": 2, "diagnostics": [error]})
        expect("included: the error on main.f2's include line", published[main_uri], {
            "uri": main_uri, "version": 1, "diagnostics": [{
                "range": rng(1, 9, 25), "severity": 1, "source": "f2",
                "message": "in the included file parts/stage.f2:3:25: expected a number, got 'zz'",
                "relatedInformation": [{"location": loc(stage_uri, 2, 24, 26),
                                        "message": "expected a number, got 'zz'"}]}]})

        # stage.f2 includes main.f2: a cycle, reported, and nothing hangs.
        client.notify("textDocument/didChange", {"textDocument": {"uri": stage_uri, "version": 3},
                                                 "contentChanges": [{"text": STAGE + "/include ../main.f2\n"}]})
        reply = client.request("textDocument/hover", at(stage_uri, 2, 14))
        expect("included: a cycle still answers", "result" in reply, True)
        reply = client.request("shutdown")
        client.notify("exit", None)
        expect("included: exit code", client.close(), 0)
    finally:
        shutil.rmtree(directory)


def main():
    included_session(sys.argv[1])
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
                     "- parts of robot:\n"
                     "  - `body` on the root, pivot (0, -105, 0)\n"
                     "    - `body.torso`: cylinder r 40, h 150 centred at (0, 75, 0)\n"
                     "    - `head`, pivot (0, 150, 0)\n"
                     "      - `head.face`: box 60 × 50 × 50 centred at (0, 25, 0)\n"
                     "      - `head.leye`: sphere r 6 centred at (-14, 30, 25) (keeps its colour)\n"
                     "      - `head.reye`: sphere r 6 centred at (14, 30, 25) (keeps its colour)\n"
                     "    - `lhand`, pivot (-52, 140, 0)\n"
                     "      - `lhand.arm`: cylinder r 10, h 100 centred at (0, -50, 0)\n"
                     "    - `rhand`, pivot (52, 140, 0)\n"
                     "      - `rhand.arm`: cylinder r 10, h 100 centred at (0, -50, 0)\n"
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
