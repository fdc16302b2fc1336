#!/usr/bin/env python3
"""`prime film OUT FRAME...`: PNG frames as a film (docs/user-guide.md, "Films").

Frames made by the real `prime trace` of a Malone scene from three eyes:
  - a GIF of the 8514/A views (at most 256 colours) holds each frame's
    pixels exactly; read back here (blocks, NETSCAPE2.0 loop count, the
    delays of each graphics control extension adding up to round(100 n / fps),
    LZW decoded); the same frames give the same bytes;
  - a GIF of the true-colour frames says how many frames it quantized;
  - frames of two sizes, an unknown extension, a video without ffmpeg on
    PATH: refused, naming what was expected and found, nothing written;
  - a video through a stub `ffmpeg` first on PATH, which records its
    arguments and the bytes piped to it: frames x W x H x 3 bytes of RGB24,
    the size and the frame rate in its arguments, its output renamed to OUT;
    when it fails (exit 3, having read nothing), its status is reported,
    exit 1, and neither OUT nor a temporary is left.

Run: check_film.py PRIME_EXE REPO_ROOT
"""
import json
import os
import struct
import subprocess
import sys
import tempfile
import zlib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../support"))
from prime_checks import Checks, png_rows

PRIME, ROOT = sys.argv[1], sys.argv[2]
SCENE = os.path.join(ROOT, "scenes/malone/doc-sphere.mal")
EYES = [("1.5", "1", "4"), ("0", "1.5", "4"), ("-1.5", "1", "4")]
W, H = 64, 48
checks = Checks(PRIME)
check = checks.check


def run(args, path=None, cwd=None):
    env = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="")
    if path is not None:
        env["PATH"] = path
    return subprocess.run([PRIME] + args, capture_output=True, text=True, env=env, cwd=cwd)


def lzw_decode(min_code, data, count):
    """GIF's variable-length-code LZW: `count` palette indices."""
    clear, end = 1 << min_code, (1 << min_code) + 1
    size, table, prev, out = min_code + 1, None, None, bytearray()
    bits, nbits, pos = 0, 0, 0
    while len(out) < count:
        while nbits < size:
            if pos >= len(data):
                return bytes(out)
            bits |= data[pos] << nbits
            pos, nbits = pos + 1, nbits + 8
        code, bits, nbits = bits & ((1 << size) - 1), bits >> size, nbits - size
        if code == clear:
            table = [bytes([i]) for i in range(clear)] + [b"", b""]
            size, prev = min_code + 1, None
            continue
        if code == end:
            break
        if prev is None:
            entry = table[code]
        elif code < len(table):
            entry = table[code]
            table.append(prev + entry[:1])
        else:
            entry = prev + prev[:1]
            table.append(entry)
        out += entry
        prev = entry
        if len(table) == 1 << size and size < 12:
            size += 1
    return bytes(out)


def read_gif(path):
    """Screen size, loop count, and per frame (delay, RGB bytes)."""
    data = open(path, "rb").read()
    assert data[:6] == b"GIF89a", data[:6]
    width, height, flags = struct.unpack("<HHB", data[6:11])
    pos = 13 + (3 << ((flags & 7) + 1) if flags & 0x80 else 0)
    loop, delay, frames = None, None, []

    def blocks(p):
        body = b""
        while data[p]:
            body += data[p + 1:p + 1 + data[p]]
            p += 1 + data[p]
        return body, p + 1

    while data[pos] != 0x3B:
        if data[pos] == 0x21:
            label = data[pos + 1]
            body, pos = blocks(pos + 2)
            if label == 0xF9:
                delay = struct.unpack("<H", body[1:3])[0]
            elif label == 0xFF and body[:11] == b"NETSCAPE2.0":
                loop = struct.unpack("<H", body[12:14])[0]
        elif data[pos] == 0x2C:
            x, y, w, h, f = struct.unpack("<HHHHB", data[pos + 1:pos + 10])
            assert (x, y, w, h) == (0, 0, width, height), (x, y, w, h)
            assert f & 0x80, "a frame without its local colour map"
            n = 2 << (f & 7)
            table = data[pos + 10:pos + 10 + 3 * n]
            pos += 10 + 3 * n
            min_code = data[pos]
            body, pos = blocks(pos + 1)
            indices = lzw_decode(min_code, body, w * h)
            rgb = b"".join(table[3 * i:3 * i + 3] for i in indices)
            frames.append((delay, rgb))
            delay = None
        else:
            raise AssertionError(f"unexpected block {data[pos]:#x} at byte {pos}")
    return width, height, loop, frames


def write_png(path, width, height, pixel):
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y))
                    for y in range(height))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(
            ">I", zlib.crc32(kind + body))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2,
                                                                    0, 0, 0))
                + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def leftovers(d):
    return [n for n in os.listdir(d) if ".prime-tmp." in n]


with tempfile.TemporaryDirectory() as tmp:
    true_frames, frames_8514 = [], []
    for k, eye in enumerate(EYES):
        t, e = os.path.join(tmp, f"f{k + 1:04}.png"), os.path.join(tmp, f"s{k + 1:04}.png")
        r = run(["trace", SCENE, "--eye", *eye, "--look-at", "0", "0", "0", "--up", "0", "1", "0",
                 "--fov", "35", "--size", str(W), str(H), "--png", t, "--png-8514", e, "-q",
                 "--no-window"])
        if not check(r.returncode == 0, f"trace frame {k + 1}: {r.stderr.strip()}"):
            sys.exit(checks.report("prime film"))
        true_frames.append(t)
        frames_8514.append(e)
    check(len({open(f, "rb").read() for f in frames_8514}) == 3, "the three eyes make three frames")

    # The 8514/A views: exact, in order, at 12.5 fps (8 hundredths each), twice.
    gif = os.path.join(tmp, "screen.gif")
    r = run(["film", gif, *frames_8514, "--fps", "12.5", "--loop", "2"])
    check(r.returncode == 0 and r.stdout.strip() ==
          f"wrote {gif} (3 frames, {W} x {H}, 12.5 fps, 0.24 s)",
          f"film of the 8514/A frames: exit {r.returncode}: {r.stdout.strip()} {r.stderr.strip()}")
    check("quantized" not in r.stderr, f"the 8514/A frames need no quantizing: {r.stderr.strip()}")
    width, height, loop, frames = read_gif(gif)
    check((width, height) == (W, H), f"GIF screen {width} x {height}")
    check(loop == 2, f"NETSCAPE2.0 loop count 2, found {loop}")
    check(len(frames) == 3, f"3 frames, found {len(frames)}")
    check([d for d, _ in frames] == [8, 8, 8], f"delays 8, 8, 8: {[d for d, _ in frames]}")
    for k, (_, rgb) in enumerate(frames):
        check(rgb == b"".join(png_rows(frames_8514[k])), f"GIF frame {k + 1} is its PNG exactly")
    first = open(gif, "rb").read()
    r = run(["film", gif, *frames_8514, "--fps", "12.5", "--loop", "2"])
    check(r.returncode == 0 and open(gif, "rb").read() == first, "the same frames, the same bytes")

    # True colour, 29.97 fps by default rounding: delays 3, 4, 3 (10 = round(300 / 29.97)).
    gif = os.path.join(tmp, "true.gif")
    r = run(["film", gif, *true_frames, "--fps", "29.97"])
    check(r.returncode == 0 and "3 of 3 frames had more than 256 colours" in r.stderr,
          f"true-colour frames are quantized, and said: {r.stderr.strip()}")
    _, _, loop, frames = read_gif(gif)
    check(loop == 0, f"--loop defaults to 0 (forever), found {loop}")
    delays = [d for d, _ in frames]
    check(delays == [3, 4, 3] and sum(delays) == round(300 / 29.97), f"delays at 29.97: {delays}")

    # Refusals: nothing written, exit non-zero, the file and both sizes named.
    small = os.path.join(tmp, "small.png")
    write_png(small, 32, 24, lambda x, y: (x, y, 0))
    bad = os.path.join(tmp, "bad.gif")
    r = run(["film", bad, frames_8514[0], small, frames_8514[1]])
    check(r.returncode == 1 and small in r.stderr and "32 x 24" in r.stderr and
          f"{W} x {H}" in r.stderr and frames_8514[0] in r.stderr,
          f"a frame of another size is refused, naming it and both sizes: {r.stderr.strip()}")
    check(not os.path.exists(bad) and not leftovers(tmp), "a refused film leaves nothing")
    r = run(["film", os.path.join(tmp, "film.avi"), *frames_8514])
    check(r.returncode != 0 and "film.avi" in r.stderr and ".gif, .mp4, .mkv, .webm, .mov" in
          r.stderr and "'.avi'" in r.stderr,
          f"an unknown kind is refused, listing the kinds: {r.stderr.strip()}")
    mp4 = os.path.join(tmp, "film.mp4")
    r = run(["film", mp4, *frames_8514], path="")
    check(r.returncode == 1 and "ffmpeg is not installed (apt install ffmpeg), or write "
          f"{os.path.join(tmp, 'film.gif')} natively" in r.stderr,
          f"without ffmpeg: said, with the way out: {r.stderr.strip()}")
    check(not os.path.exists(mp4), "without ffmpeg nothing is written")
    r = run(["film", gif, *frames_8514, "--fps", "0"])
    check(r.returncode == 2 and "--fps" in r.stderr, f"--fps 0 is refused: {r.stderr.strip()}")

    # A stub ffmpeg: its arguments, the bytes it was given, its output.
    stub_dir = os.path.join(tmp, "bin")
    os.mkdir(stub_dir)
    record = os.path.join(tmp, "ffmpeg-call.json")
    with open(os.path.join(stub_dir, "ffmpeg"), "w") as f:
        f.write(f"""#!{sys.executable}
import json, os, sys
status = int(os.environ.get("STUB_EXIT", "0"))
n = 0
if status == 0:
    while True:
        chunk = sys.stdin.buffer.read(65536)
        if not chunk:
            break
        n += len(chunk)
json.dump({{"argv": sys.argv[1:], "bytes": n}}, open({record!r}, "w"))
if status == 0:
    open(sys.argv[-1], "wb").write(b"stub video")
sys.exit(status)
""")
    os.chmod(os.path.join(stub_dir, "ffmpeg"), 0o755)
    path = stub_dir + os.pathsep + os.environ.get("PATH", "")
    r = run(["film", mp4, *true_frames, "--fps", "29.97"], path=path)
    call = json.load(open(record)) if os.path.exists(record) else {"argv": [], "bytes": -1}
    argv = call["argv"]
    check(r.returncode == 0 and r.stdout.strip() ==
          f"wrote {mp4} (3 frames, {W} x {H}, 29.97 fps, 0.10 s)",
          f"film through ffmpeg: exit {r.returncode}: {r.stdout.strip()} {r.stderr.strip()}")
    check(call["bytes"] == 3 * W * H * 3, f"3 frames of RGB24 piped: {call['bytes']} bytes")
    joined = " ".join(argv)
    for part in ("-f rawvideo -pix_fmt rgb24", f"-s {W}x{H}", "-framerate 29.97", "-i -",
                 "-c:v libx264", "-pix_fmt yuv420p", "-crf 18", "-movflags +faststart",
                 "-vf pad=ceil(iw/2)*2:ceil(ih/2)*2"):
        check(part in joined, f"ffmpeg's arguments hold '{part}': {joined}")
    check(bool(argv) and argv[-1].startswith(mp4 + ".prime-tmp."),
          f"ffmpeg writes a temporary beside OUT: {argv[-1:]}")
    check("prime: film: running ffmpeg -hide_banner" in r.stderr and
          "'pad=ceil(iw/2)*2:ceil(ih/2)*2'" in r.stderr,
          f"the ffmpeg command is printed as a shell reads it: {r.stderr.strip()}")
    check(os.path.exists(mp4) and open(mp4, "rb").read() == b"stub video" and not leftovers(tmp),
          "ffmpeg's output is renamed to OUT, no temporary left")

    # ffmpeg fails without reading (frames of 640 x 480 fill the pipe): the
    # status said, exit 1, OUT untouched and no temporary left.
    big = []
    for k in range(3):
        big.append(os.path.join(tmp, f"big{k}.png"))
        write_png(big[-1], 640, 480, lambda x, y, k=k: (x & 255, y & 255, k))
    webm = os.path.join(tmp, "film.webm")
    r = subprocess.run([PRIME, "film", webm, *big], capture_output=True, text=True,
                       env=dict(os.environ, PATH=path, STUB_EXIT="3", DISPLAY=""))
    check(r.returncode == 1 and "exit status 3" in r.stderr and webm in r.stderr,
          f"a failing ffmpeg: its status said, exit 1: {r.returncode} {r.stderr.strip()}")
    check(not os.path.exists(webm) and not leftovers(tmp), "a failing ffmpeg leaves nothing")
    argv = json.load(open(record))["argv"]
    check("-c:v libvpx-vp9" in " ".join(argv) and argv[len(argv) - argv[::-1].index("-f")] == "webm",
          f"webm: VP9 in WebM: {' '.join(argv)}")

sys.exit(checks.report("prime film"))
