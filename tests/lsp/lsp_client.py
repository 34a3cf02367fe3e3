"""A minimal Language Server Protocol client over a child process's pipes
(python3 standard library only), for the protocol tests of `f2 lsp`."""
import json
import os
import select
import subprocess

# A guard against a hung server, not a timing assumption: every read waits
# for the reply it needs and fails the test only if the server never answers.
HANG_GUARD_SECONDS = 60


class Client:
    def __init__(self, command):
        self.proc = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE)
        self.buffer = b""
        self.next_id = 1
        self.notifications = []

    def send_raw(self, data):
        self.proc.stdin.write(data)
        self.proc.stdin.flush()

    def send(self, message):
        message = dict(message, jsonrpc="2.0")
        body = json.dumps(message, ensure_ascii=False).encode("utf-8")
        self.send_raw(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def notify(self, method, params):
        self.send({"method": method, "params": params})

    def request(self, method, params=None):
        """Sends a request and returns its response (notifications that come
        first are kept in self.notifications)."""
        request_id = self.next_id
        self.next_id += 1
        message = {"id": request_id, "method": method}
        if params is not None:
            message["params"] = params
        self.send(message)
        while True:
            message = self.read()
            if message.get("id") == request_id and "method" not in message:
                return message
            self.notifications.append(message)

    def read(self):
        """The next message from the server."""
        while True:
            header_end = self.buffer.find(b"\r\n\r\n")
            if header_end >= 0:
                header = self.buffer[:header_end].decode("ascii")
                length = None
                for line in header.split("\r\n"):
                    name, _, value = line.partition(":")
                    if name.strip().lower() == "content-length":
                        length = int(value)
                if length is None:
                    raise AssertionError("a header without Content-Length: %r" % header)
                start = header_end + 4
                if len(self.buffer) >= start + length:
                    body = self.buffer[start:start + length]
                    self.buffer = self.buffer[start + length:]
                    return json.loads(body.decode("utf-8"))
            ready, _, _ = select.select([self.proc.stdout], [], [], HANG_GUARD_SECONDS)
            if not ready:
                raise AssertionError("the server sent nothing for %d s" % HANG_GUARD_SECONDS)
            chunk = os.read(self.proc.stdout.fileno(), 65536)
            if not chunk:
                raise AssertionError("the server closed its output; stderr: %s"
                                     % self.proc.stderr.read().decode(errors="replace"))
            self.buffer += chunk

    def next_notification(self, method):
        """The next notification `method` (kept ones first)."""
        for i, message in enumerate(self.notifications):
            if message.get("method") == method:
                return self.notifications.pop(i)
        while True:
            message = self.read()
            if message.get("method") == method:
                return message
            self.notifications.append(message)

    def close(self):
        """Ends the child; returns its exit code."""
        self.proc.stdin.close()
        code = self.proc.wait(timeout=HANG_GUARD_SECONDS)
        self.proc.stdout.close()
        self.proc.stderr.close()
        return code
