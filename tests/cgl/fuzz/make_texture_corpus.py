#!/usr/bin/env python3
"""Writes corpus/cgl_texture/: seeds for cgl_texture_fuzz.cpp, each a scene
directory in one file (the scene, then `%%cgl:<name>` files), the maps small
RLE files (legacy_io/cgl/frame.h: little-endian words, count in the high
byte, 512 scanlines of 512 pixels). Run from anywhere; rewrites the seeds."""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "corpus", "cgl_texture")



def vector(value):
    """A colour-vector as the format writes one: 10, 10, 10 and 3 to a line."""
    return "\n".join(" ".join([value] * n) for n in (10, 10, 10, 3))


GREY = vector("0.5")
FIFTY = vector("50.0")
HUNDRED = vector("100.0")


def word(count, r, g, b):
    return struct.pack("<I", count << 24 | b << 16 | g << 8 | r)


def rle(runs_of_row):
    """runs_of_row(row) -> [(count, (r, g, b)), ...] summing to 512."""
    out = bytearray()
    for row in range(512):
        for count, (r, g, b) in runs_of_row(row):
            out += word(count, r, g, b)
    return bytes(out)


def solid(rgb):
    return rle(lambda row: [(255, rgb), (255, rgb), (2, rgb)])


def checks(a, b):
    def row(y):
        first, second = (a, b) if (y // 128) % 2 == 0 else (b, a)
        return [(128, first), (128, second), (128, first), (128, second)]
    return rle(row)


def scene(surfaces, nodes=None):
    """A scene with the given surface records (each a list of lines), a sphere
    and a square on the first surfaces."""
    n = len(surfaces)
    nodes = nodes or ["1 sphere 00 02 1 0 0 0 0.5 x y",
                      "2 polygon 00 00 %d 4 1 2 3 4" % min(2, n)]
    lines = ["* a textured scene", "1 2 4 %d 1 %d 1" % (n, len(nodes)),
             "1 depth 2", "1 eye 0 0 3.5", "2 sight towards 0 0 0",
             "1 -1 0 -1", "2 -1 0 1", "3 1 0 1", "4 1 0 -1"]
    for k, s in enumerate(surfaces, 1):
        lines.append(s[0].replace("#", str(k)))
        lines += s[1:]
    lines += ["0.0005", FIFTY, "1 infinity 1 1 1 0.0006", HUNDRED] + nodes
    return ("\n".join(lines) + "\n").encode()


def textured(path, model="lambert"):
    extra = "7.0" if model == "lambert" else "0.0 2.5 25.0"
    return ["# %s textured 0.0 0.0 0.0" % model, extra, "%s 1.0 1.0" % path]


def plain():
    return ["# lambert normal 0 0 0", "7.0", GREY]


def files(*named):
    """(name, content) pairs as marker-introduced files."""
    out = b""
    for name, content in named:
        out += b"%%cgl:" + name.encode() + b"\n" + content
    return out


def main():
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):
        os.remove(os.path.join(OUT, f))
    red = solid((255, 0, 0))
    board = checks((0, 160, 0), (0, 0, 160))
    seeds = {
        # the path as written, relative to the scene
        "relative.txt": scene([textured("textures/board.rle"), plain()])
        + files(("textures/board.rle", board)),
        # the document's absolute path: found by base name beside the scene
        "by-base-name.txt": scene([textured("/u/majsweeney/textures/red"), plain()])
        + files(("red.rle", red)),
        # by base name in textures/, a Phong surface
        "in-textures.txt": scene([textured("red", "phong"), plain()])
        + files(("textures/red.rle", red)),
        # `last`: the previous textured surface's map again
        "last.txt": scene([textured("board.rle"), textured("last")])
        + files(("board.rle", board)),
        # `last` on the first textured surface
        "last-first.txt": scene([plain(), textured("last")]),
        # one map named by three surfaces
        "same-map-thrice.txt": scene([textured("red.rle"), textured("red.rle"),
                                      textured("./red.rle")]) + files(("red.rle", red)),
        # not found, and outside the scene's directory
        "missing.txt": scene([textured("../elsewhere/board.rle"), plain()]),
        # a map cut short, a map with a zero count, a map too long
        "truncated.txt": scene([textured("red.rle"), plain()]) + files(("red.rle", red[:4001])),
        "zero-count.txt": scene([textured("red.rle"), plain()])
        + files(("red.rle", word(0, 1, 2, 3) + red[4:])),
        "too-long.txt": scene([textured("red.rle"), plain()])
        + files(("red.rle", red + word(1, 0, 0, 0))),
    }
    total = 0
    for name, content in seeds.items():
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(content)
        total += len(content)
    assert total < 200_000, total
    assert all(len(c) <= 16384 for c in seeds.values())


if __name__ == "__main__":
    main()
