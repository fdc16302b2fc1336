"""A small client of the Chrome DevTools Protocol over its WebSocket, from the
standard library only (Debian's python3 has no websocket module): enough for
tests/web to drive headless Chromium: start it, open a page, evaluate
JavaScript (awaiting promises), take a screenshot."""
import base64
import json
import os
import shutil
import socket
import struct
import subprocess
import tempfile
import time
import urllib.request


class Browser:
    def __init__(self, width=1600, height=1000):
        self.profile = tempfile.mkdtemp(prefix="prime-chromium-")
        port = _free_port()
        chromium = shutil.which("chromium") or "/usr/bin/chromium"
        # The flags Debian's chromium needs headless as root on a machine
        # without a network (docs/web.md): no sandbox (root), no GPU, and none
        # of the background connections it would try at every start.
        self.process = subprocess.Popen(
            [chromium, "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic",
             "--no-first-run", "--disable-background-networking", "--disable-component-update",
             "--disable-sync", "--disable-dev-shm-usage", f"--user-data-dir={self.profile}",
             f"--remote-debugging-port={port}", f"--window-size={width},{height}",
             "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.time() + 30
        targets = None
        while time.time() < deadline:
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=2) as r:
                    targets = [t for t in json.load(r) if t.get("type") == "page"]
                if targets:
                    break
            except OSError:
                pass
            time.sleep(0.2)
        if not targets:
            self.close()
            raise RuntimeError("chromium did not start (no DevTools page on port %d)" % port)
        self.socket = _connect(targets[0]["webSocketDebuggerUrl"])
        self.next_id = 0
        self.console = []
        self.call("Runtime.enable")
        self.call("Page.enable")

    def call(self, method, **params):
        self.next_id += 1
        mine = self.next_id
        _send(self.socket, json.dumps({"id": mine, "method": method, "params": params}))
        while True:
            message = json.loads(_receive(self.socket))
            if message.get("method") == "Runtime.consoleAPICalled":
                self.console.append(" ".join(str(a.get("value", a.get("description", "")))
                                             for a in message["params"]["args"]))
            if message.get("method") == "Runtime.exceptionThrown":
                self.console.append(json.dumps(message["params"]["exceptionDetails"])[:500])
            if message.get("id") == mine:
                if "error" in message:
                    raise RuntimeError(f"{method}: {message['error']}")
                return message.get("result", {})

    def evaluate(self, expression, timeout=300):
        """The value of a JavaScript expression (a promise is awaited)."""
        self.socket.settimeout(timeout)
        r = self.call("Runtime.evaluate", expression=expression, awaitPromise=True,
                      returnByValue=True, timeout=timeout * 1000)
        if "exceptionDetails" in r:
            raise RuntimeError("page: " + json.dumps(r["exceptionDetails"])[:800])
        return r["result"].get("value")

    def open(self, url):
        self.call("Page.navigate", url=url)
        deadline = time.time() + 60
        while time.time() < deadline:
            if self.evaluate("document.readyState") == "complete":
                return
            time.sleep(0.1)
        raise RuntimeError("the page did not load: " + url)

    def screenshot(self, path):
        data = self.call("Page.captureScreenshot", format="png")["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))

    def close(self):
        if getattr(self, "process", None):
            self.process.kill()
            self.process.wait()
            self.process = None
        shutil.rmtree(self.profile, ignore_errors=True)


def _free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


def _connect(url):
    assert url.startswith("ws://")
    hostport, path = url[5:].split("/", 1)
    host, port = hostport.split(":")
    s = socket.create_connection((host, int(port)), timeout=30)
    key = base64.b64encode(os.urandom(16)).decode()
    s.sendall((f"GET /{path} HTTP/1.1\r\nHost: {hostport}\r\nUpgrade: websocket\r\n"
               f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n"
               "Sec-WebSocket-Version: 13\r\n\r\n").encode())
    reply = b""
    while b"\r\n\r\n" not in reply:
        chunk = s.recv(4096)
        if not chunk:
            raise RuntimeError("DevTools closed the connection during the handshake")
        reply += chunk
    if b" 101 " not in reply.split(b"\r\n")[0]:
        raise RuntimeError("DevTools refused the WebSocket: " + reply.split(b"\r\n")[0].decode())
    return s


def _send(s, text):
    payload = text.encode()
    header = bytearray([0x81])  # FIN, text
    n = len(payload)
    if n < 126:
        header.append(0x80 | n)
    elif n < 65536:
        header.append(0x80 | 126)
        header += struct.pack(">H", n)
    else:
        header.append(0x80 | 127)
        header += struct.pack(">Q", n)
    mask = os.urandom(4)
    header += mask
    s.sendall(bytes(header) + bytes(b ^ mask[i % 4] for i, b in enumerate(payload)))


def _exactly(s, n):
    data = bytearray()
    while len(data) < n:
        chunk = s.recv(n - len(data))
        if not chunk:
            raise RuntimeError("DevTools closed the connection")
        data += chunk
    return bytes(data)


def _receive(s):
    message = bytearray()
    while True:
        b0, b1 = _exactly(s, 2)
        n = b1 & 0x7F
        if n == 126:
            n = struct.unpack(">H", _exactly(s, 2))[0]
        elif n == 127:
            n = struct.unpack(">Q", _exactly(s, 8))[0]
        if b1 & 0x80:
            mask = _exactly(s, 4)
            data = bytes(b ^ mask[i % 4] for i, b in enumerate(_exactly(s, n)))
        else:
            data = _exactly(s, n)
        opcode = b0 & 0x0F
        if opcode == 0x8:
            raise RuntimeError("DevTools closed the WebSocket")
        if opcode in (0x9, 0xA):  # ping / pong
            continue
        message += data
        if b0 & 0x80:
            return message.decode()
