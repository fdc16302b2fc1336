#!/usr/bin/env python3
"""Writes the texture maps of scenes/cgl/textures/ as the CGL package's
run-length encoded pictures (docs/cgl/picture-files.md): 512 x 512 pixels,
32-bit little-endian words, high 8 bits the count of pixels (1 to 255) in the
colour of the low 24 bits (blue, green, red from high to low), each scanline
encoded on its own, the top scanline first.

The document's own texture files (/u/majsweeney/textures/checkerboard and
mandrill, Appendix 1) are lost; these stand in for them (docs/cgl/deviations.md
CGL-D21):

  checkerboard.rle  8 x 8 squares of 64 x 64 pixels, green (0, 160, 0) and
                    blue (0, 0, 200), the top left square green.
  rings.rle         a procedural picture with detail in place of the mandrill
                    (it does not pretend to be one): rings 16 pixels wide about
                    the centre, alternately bright and dark, coloured by octant
                    so that the picture's orientation on a surface can be read
                    (counter-clockwise from the right of the centre, above the
                    horizontal: red, orange, yellow, green, cyan, blue, violet,
                    magenta).

Only integer arithmetic, so every Python 3 makes the same bytes. With --check
it writes nothing and fails when a committed file differs from what it makes
(ctest tools.cgl_textures_are_generated).

    python3 tools/cgl/textures.py [--check]
"""
import math
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.normpath(os.path.join(HERE, "..", "..", "scenes", "cgl", "textures"))
SIZE = 512

GREEN = (0, 160, 0)
BLUE = (0, 0, 200)

# The octants' colours, counter-clockwise from +x (right) with y up.
OCTANT_COLOURS = [
    (220, 30, 30),  # red
    (230, 130, 20),  # orange
    (230, 210, 30),  # yellow
    (30, 170, 40),  # green
    (30, 190, 190),  # cyan
    (30, 60, 210),  # blue
    (120, 40, 190),  # violet
    (200, 40, 160),  # magenta
]


def pack(rgb):
    r, g, b = rgb
    return r | g << 8 | b << 16


def encode_rle(rows):
    """rows: SIZE rows of SIZE packed colours, the top row first."""
    out = bytearray()
    for row in rows:
        assert len(row) == SIZE
        x = 0
        while x < SIZE:
            colour = row[x]
            n = 1
            while x + n < SIZE and n < 255 and row[x + n] == colour:
                n += 1
            out += struct.pack("<I", n << 24 | colour)
            x += n
    return bytes(out)


def checkerboard():
    rows = []
    for y in range(SIZE):  # y: image row from the top
        rows.append([pack(GREEN if (y // 64 + x // 64) % 2 == 0 else BLUE) for x in range(SIZE)])
    return rows


def octant(dx, dy):
    """0..7 counter-clockwise from +x; dx, dy odd (never 0), y up."""
    ax, ay = abs(dx), abs(dy)
    if dx > 0 and dy > 0:
        return 0 if ax > ay else 1
    if dx < 0 < dy:
        return 2 if ay > ax else 3
    if dx < 0 and dy < 0:
        return 4 if ax > ay else 5
    return 6 if ay > ax else 7


def rings():
    rows = []
    for y in range(SIZE):
        row = []
        for x in range(SIZE):
            # Twice the offset from the centre (255.5, 255.5): odd integers.
            dx, dy = 2 * x - (SIZE - 1), (SIZE - 1) - 2 * y
            ring = math.isqrt(dx * dx + dy * dy) // 32  # radius // 16
            r, g, b = OCTANT_COLOURS[octant(dx, dy)]
            if ring % 2:
                r, g, b = r * 9 // 20, g * 9 // 20, b * 9 // 20
            row.append(pack((r, g, b)))
        rows.append(row)
    return rows


TEXTURES = {
    "checkerboard.rle": checkerboard,
    "rings.rle": rings,
}


def main():
    check = "--check" in sys.argv[1:]
    status = 0
    for name, make in TEXTURES.items():
        data = encode_rle(make())
        path = os.path.join(OUT, name)
        if check:
            with open(path, "rb") if os.path.exists(path) else open(os.devnull, "rb") as f:
                if f.read() != data:
                    print("cgl textures: %s differs from what tools/cgl/textures.py makes" % path,
                          file=sys.stderr)
                    status = 1
        else:
            os.makedirs(OUT, exist_ok=True)
            tmp = path + ".tmp"
            with open(tmp, "wb") as f:
                f.write(data)
            os.replace(tmp, path)
            print("wrote %s (%d bytes)" % (path, len(data)))
    if check and status == 0:
        print("cgl textures: %d files as generated" % len(TEXTURES))
    return status


if __name__ == "__main__":
    sys.exit(main())
