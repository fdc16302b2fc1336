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
    """The RGB rows of an 8-bit RGB or 8-bit palette, non-interlaced PNG (what
    prime writes: an 8514/A picture is indexed), palette entries as RGB."""
    data = open(path, "rb").read()
    pos, idat, width, height, kind_of, plte = 8, b"", 0, 0, 2, b""
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height = struct.unpack(">II", body[:8])
            kind_of = body[9]
        elif kind == b"PLTE":
            plte = body
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    bpp = 1 if kind_of == 3 else 3
    raw, stride, rows, prev = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
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
        prev = line
        if bpp == 1:
            line = b"".join(plte[3 * v:3 * v + 3] for v in line)
        rows.append(bytes(line))
    return rows


def png_text(path):
    """The tEXt chunks of a PNG, as a dict."""
    data, pos, text = open(path, "rb").read(), 8, {}
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        if kind == b"tEXt":
            key, _, value = data[pos + 8:pos + 8 + n].partition(b"\0")
            text[key.decode("latin-1")] = value.decode("latin-1")
        pos += 12 + n
    return text


def same_pixels(a, b):
    """Whether two PNGs show the same pixels (whatever their text says)."""
    return png_size(a) == png_size(b) and png_rows(a) == png_rows(b)
