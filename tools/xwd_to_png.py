#!/usr/bin/env python3
"""Converts an xwd capture (24/32-bit TrueColor ZPixmap, as Xvfb gives) to a
PNG, with the standard library only: how the window screenshots in
docs/prime/images/ were made from `xwd -id WINDOW` (docs/prime/palette.md)."""
import struct
import sys
import zlib


def main(src, dst):
    data = open(src, "rb").read()
    h = struct.unpack(">25I", data[:100])
    header_size, width, height = h[0], h[4], h[5]
    byte_order, bpp, bpl, ncolors = h[7], h[11], h[12], h[19]
    if bpp != 32:
        sys.exit(f"{src}: {bpp} bits per pixel, only 32 is handled")
    masks = h[14:17]
    pixels = data[header_size + 12 * ncolors:]
    fmt = "<I" if byte_order == 0 else ">I"
    shifts = [(m & -m).bit_length() - 1 for m in masks]
    rows = bytearray()
    for y in range(height):
        rows.append(0)
        line = pixels[y * bpl:y * bpl + 4 * width]
        for (v,) in struct.iter_unpack(fmt, line):
            rows += bytes(((v & m) >> s) & 255 for m, s in zip(masks, shifts))
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b"")
    open(dst, "wb").write(png)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: xwd_to_png.py IN.xwd OUT.png")
    main(sys.argv[1], sys.argv[2])
