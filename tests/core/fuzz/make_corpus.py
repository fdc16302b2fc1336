#!/usr/bin/env python3
"""Writes corpus/png_image/: tiny PNGs for png_image_fuzz.cpp, made here with
zlib (no imaging library): RGB, grey, grey + alpha, RGBA, an indexed one with
a tRNS chunk, 1-bit and 16-bit ones, an interlaced one, and a few broken
ones. Run from anywhere; rewrites the seeds."""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "corpus", "png_image")


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png(width, height, depth, colour, rows, extra=b"", interlace=0):
    """rows: the raw scanlines (without filter bytes)."""
    ihdr = struct.pack(">IIBBBBB", width, height, depth, colour, 0, 0, interlace)
    raw = b"".join(b"\x00" + r for r in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + extra
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):
        os.remove(os.path.join(OUT, f))
    w, h = 4, 3
    rgb = [b"".join(bytes((x * 60, y * 100, 200)) for x in range(w)) for y in range(h)]
    rgba = [b"".join(bytes((x * 60, y * 100, 200, 128 + x)) for x in range(w)) for y in range(h)]
    grey = [bytes(x * 80 for x in range(w)) for _ in range(h)]
    grey_alpha = [b"".join(bytes((x * 80, 255 - x)) for x in range(w)) for _ in range(h)]
    rgb16 = [b"".join(struct.pack(">HHH", x * 16000, y * 30000, 65535) for x in range(w))
             for y in range(h)]
    grey16 = [b"".join(struct.pack(">H", x * 20000 + y) for x in range(w)) for y in range(h)]
    palette = chunk(b"PLTE", bytes((255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255)))
    indexed = [bytes((x + y) % 4 for x in range(w)) for y in range(h)]
    # 1 bit a pixel, 2 colours: 8 pixels a byte
    bits = [bytes((0b10110010,)) for _ in range(h)]
    seeds = {
        "rgb8.png": png(w, h, 8, 2, rgb),
        "rgba8.png": png(w, h, 8, 6, rgba),
        "grey8.png": png(w, h, 8, 0, grey),
        "grey-alpha8.png": png(w, h, 8, 4, grey_alpha),
        "rgb16.png": png(w, h, 16, 2, rgb16),
        "grey16.png": png(w, h, 16, 0, grey16),
        "indexed.png": png(w, h, 8, 3, indexed, palette),
        "indexed-trns.png": png(w, h, 8, 3, indexed, palette + chunk(b"tRNS", bytes((0, 128)))),
        "indexed1.png": png(8, h, 1, 3, bits, chunk(b"PLTE", bytes((0, 0, 0, 255, 255, 255)))),
        # Adam7 on one pixel: only the first pass has a row
        "interlaced.png": png(1, 1, 8, 2, [b"\x10\x20\x30"], interlace=1),
        "gamma.png": png(w, h, 8, 2, rgb, chunk(b"gAMA", struct.pack(">I", 45455))),
        # broken: a cut IDAT, a bad CRC, a header claiming 65535 x 65535
        "truncated.png": png(w, h, 8, 2, rgb)[:50],
        "bad-crc.png": png(w, h, 8, 2, rgb)[:29] + b"\0\0\0\0" + png(w, h, 8, 2, rgb)[33:],
        "huge-header.png": png(65535, 65535, 8, 2, [b"\x00\x00\x00"]),
    }
    total = 0
    for name, content in seeds.items():
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(content)
        total += len(content)
    assert total < 200_000, total


if __name__ == "__main__":
    main()
