"""What the end-to-end check scripts share: running the real `prime` without
a display, and collecting the checks that fail.

    checks = Checks(PRIME_EXE)
    r = checks.run(["trace", scene, "-q"])
    checks.check(r.returncode == 0, "trace exits 0")
    sys.exit(checks.report("camera hand-off"))
"""
import os
import struct
import subprocess
import zlib


class Checks:
    def __init__(self, prime):
        self.prime = prime
        self.failures = []

    def run(self, args):
        env = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="")
        return subprocess.run([self.prime] + args, capture_output=True, text=True, env=env)

    def check(self, ok, what):
        if not ok:
            self.failures.append(what)
        return ok

    def report(self, what):
        """Prints the failures and a last line; returns the exit status."""
        for f in self.failures:
            print("FAIL:", f)
        print(f"{what}: {len(self.failures)} failure(s)")
        return 1 if self.failures else 0


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    return struct.unpack(">II", head[16:24])


def png_rows(path):
    """The RGB rows of an 8-bit RGB, non-interlaced PNG (what prime writes)."""
    data = open(path, "rb").read()
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height = struct.unpack(">II", body[:8])
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), width * 3, [], bytearray(width * 3)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b, c = prev[i], prev[i - 3] if i >= 3 else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return rows
