#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets, tests/prime/fuzz/corpus/<target>/.

    tests/prime/fuzz/make_corpus.py [path/to/prime]     (default build/release/src/cli/prime)

The seeds are the real files of scenes/prime/default and tests/prime/data/sphere
(copied to a temporary directory and modelled there with `prime model`), plus
a few hand-made edge cases. Each corpus is rewritten from scratch; keep the
total small (< 200 KB): libFuzzer grows its own corpus from these in the
build tree.
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
CORPUS = os.path.join(HERE, "corpus")
MARKER = b"%%prime:"
SCENES = {"default": os.path.join(ROOT, "scenes", "prime", "default"),
          "sphere": os.path.join(ROOT, "tests", "prime", "data", "sphere")}
TEXT_SUBDIRS = ["", "prim", "bound", "obj", "obj/Copy", "map", "light"]


# A scene with O entries (CopyPrim, prim/A<n>.txt), CopyObj, a pyramid and a
# bound: modelled and seeded like the two real scenes.
EDGE_COPIES = [
    ("Model.txt", b"AddObj d1.txt\nAddObj d2.txt\nAddToObjList 2\nCopyObj O2 O3 c1.txt\n"
                  b"AddToObjList 3\nAddMap m.txt\nAddMap m0.txt\n"),
    ("obj/H1.txt", b"0.1 0.2 0.3 0.4 0.5 0.999 2 2 1.5\n"),
    ("obj/D1.txt", b"3\n- 1 2\nB 1\nS 1\nNULL\n"),
    ("obj/H2.txt", b"0.1 0.2 0.3 0.4 0.5 0.999 2 2 1.5\n"),
    ("obj/D2.txt", b"3\n+ 1 2\nO 1 1\nY 1\nB 2\n"),
    ("obj/Copy/c1.txt", b"1 1 1\n0 -400 0\n0 0 90\n0 0 0\n"),
    ("prim/A1.txt", b"2 2 2\n10 0 0\n0 45 0\n0.5 0.5 0.5\n"),
    ("prim/B1.txt", b"B\n100 100 100\n0 0 0\n0 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n"),
    ("prim/S1.txt", b"S\n60 60 60\n50 50 0\n0 0 0\n0 0 0\n1 1\n0\n"),
    ("prim/Y1.txt", b"Y\n50 80 50\n0 0 200\n30 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1\n2\n"),
    ("bound/B2.txt", b"B\n400 400 400\n-10 -10 -10\n0 0 0\n0 0 0\n"),
    ("map/m.txt", b"1\n2 1\n0.1 0.2\n0.3 0.4\n0.5 0.6\n"),
    # Map 0: the copies of the sphere become pyramids (K33), whose other surfaces name map 0.
    ("map/m0.txt", b"0\n1 1\n0.5\n0.5\n0.5\n"),
    ("light/light.txt", b"0.2 0.2 0.2\n1\n0 1000 -1000\n1 1 1\n"),
]


def model(prime, src, dst):
    """Copies the text inputs of scene `src` to `dst` and runs prime model there."""
    for sub in TEXT_SUBDIRS:
        os.makedirs(os.path.join(dst, sub), exist_ok=True)
        d = os.path.join(src, sub)
        if not os.path.isdir(d):  # a scene needs no bound/ or obj/Copy/
            continue
        for name in sorted(os.listdir(d)):
            p = os.path.join(d, name)
            if os.path.isfile(p) and (name.endswith(".txt") or sub == "obj/Copy"):
                shutil.copy(p, os.path.join(dst, sub, name))
    subprocess.run([prime, "model", dst], check=True, stdout=subprocess.DEVNULL)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def files_of(scene, subs, keep):
    """(relative path, bytes) of the files of `scene` in `subs` for which keep(name) holds."""
    out = []
    for sub in subs:
        d = os.path.join(scene, sub)
        if not os.path.isdir(d):
            continue
        for name in sorted(os.listdir(d)):
            p = os.path.join(d, name)
            if os.path.isfile(p) and keep(name):
                out.append((os.path.join(sub, name) if sub else name, read(p)))
    return out


def bundle(files):
    """One fuzz input holding a scene directory (tests/prime/fuzz/fuzz_support.h)."""
    out = b""
    for rel, data in files:
        assert MARKER not in data, rel
        out += MARKER + rel.encode() + b"\n" + data
    return out


def prim_record(type_letter, transform, inverse, maps, priority, aligned=False):
    b = type_letter.encode() + (b"\0" if aligned else b"")
    for m in (transform, inverse):
        b += struct.pack("<16d", *[v for row in m for v in row])
    b += struct.pack("<12h", *[v for pair in maps for v in pair]) + struct.pack("<h", priority)
    return b + struct.pack("<d", 0.0)


def obj_file(entries, bound=-1, hue=(0.1, 0.2, 0.3, 0.4, 0.5, 0.999, 2.0, 2.0, 1.5)):
    b = struct.pack("<hh9d", len(entries), bound, *hue)
    for op, l, r in entries:
        b += op.encode() + b"\0\0\0" + struct.pack("<hh", l, r)
    return b


def graph(across, down, inclusive, value=1):
    n = (across + 1) * (down + 1) if inclusive else across * down
    return struct.pack("<hhh", 1, across, down) + struct.pack("<%dh" % n, *[(value + i) % 300 - 40 for i in range(n)])


def main():
    prime = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/release/src/cli/prime"))
    tmp = tempfile.mkdtemp(prefix="prime-corpus-")
    try:
        built = {}
        for name, src in SCENES.items():
            built[name] = os.path.join(tmp, name)
            model(prime, src, built[name])
        edge = os.path.join(tmp, "edge-copies-src")
        for rel, data in EDGE_COPIES:
            os.makedirs(os.path.dirname(os.path.join(edge, rel)), exist_ok=True)
            with open(os.path.join(edge, rel), "wb") as f:
                f.write(data)
        for sub in TEXT_SUBDIRS:
            os.makedirs(os.path.join(edge, sub), exist_ok=True)
        built["edge-copies"] = os.path.join(tmp, "edge-copies")
        model(prime, edge, built["edge-copies"])
        write_all(built)
    finally:
        shutil.rmtree(tmp)


def write_all(built):
    seeds = {}

    def add(target, name, data):
        seeds.setdefault(target, {})[name] = data

    ident = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]
    for scene, d in built.items():
        prims = read(os.path.join(d, "prim", "PrimFile"))
        add("prim_file", scene + "-PrimFile", prims)
        # The word-aligned layout (Turbo C -a): a zero byte after each type byte.
        aligned = b"".join(prims[i:i + 1] + b"\0" + prims[i + 1:i + 291] for i in range(0, len(prims), 291))
        add("prim_file", scene + "-PrimFile-aligned", aligned)
        add("obj_list", scene + "-List", read(os.path.join(d, "obj", "List")))
        for rel, data in files_of(d, ["obj"], lambda n: n.startswith("O") and n[1:].isdigit()):
            add("obj_file", scene + "-" + os.path.basename(rel), data)
        for rel, data in files_of(d, ["map"], lambda n: n.endswith("_R.map")):
            add("map_file", scene + "-" + os.path.basename(rel), data)
        # Text inputs, one reader each (tests/prime/fuzz/text_inputs_fuzz.cpp).
        for rel, data in files_of(d, TEXT_SUBDIRS, lambda n: n.endswith(".txt")):
            base = os.path.basename(rel)
            kind = {"Model.txt": "M", "light.txt": "l"}.get(base)
            if kind is None:
                sub = os.path.dirname(rel)
                kind = {"prim": "a" if base.startswith("A") else "p", "bound": "b", "map": "m",
                        "obj/Copy": "a"}.get(sub)
                if sub == "obj":
                    kind = "h" if base.startswith("H") else "d"
            add("text_inputs", "%s-%s" % (scene, rel.replace("/", "-")), kind.encode() + data)
        for rel, data in files_of(d, ["obj/Copy"], lambda n: True):
            add("text_inputs", "%s-%s" % (scene, rel.replace("/", "-")), b"a" + data)
        # Whole scenes: the text inputs for the modeller, the databases for the loader.
        text = files_of(d, TEXT_SUBDIRS, lambda n: n.endswith(".txt"))
        text += [(r, x) for r, x in files_of(d, ["obj/Copy"], lambda n: True) if (r, x) not in text]
        add("model_builder", scene, bundle(text))
        dbs = files_of(d, ["prim"], lambda n: n == "PrimFile") + \
            files_of(d, ["obj"], lambda n: n == "List" or (n.startswith("O") and n[1:].isdigit())) + \
            files_of(d, ["map"], lambda n: n.endswith(".map")) + files_of(d, ["light"], lambda n: True)
        add("scene_loader", scene, bundle(dbs))

    # Edge cases.
    add("prim_file", "empty", b"")
    add("prim_file", "one-identity-sphere", prim_record("S", ident, ident, [(1, 1)] + [(0, 0)] * 5, 1))
    add("obj_file", "header-only", obj_file([]))
    add("obj_file", "dag", obj_file([("+", 1, 1), ("-", 2, 2), ("P", 0, 0)], bound=0))
    add("obj_file", "cycle", obj_file([("+", 1, 2), ("&", 0, 2), ("P", 0, 0)]))
    add("obj_list", "empty", b"")
    add("obj_list", "odd", b"\x01\x00\x02")
    add("map_file", "1x1", struct.pack("<hhd", 1, 1, 0.5))
    add("map_file", "3x2-short", struct.pack("<hh5d", 3, 2, 0, 0.2, 0.4, 0.6, 0.8))
    add("graph_file", "inclusive-3x2", graph(3, 2, True))
    add("graph_file", "exact-4x3", graph(4, 3, False))
    add("graph_file", "inclusive-0x0", graph(0, 0, True))
    add("graph_file", "header-only-0x5", graph(0, 5, False))
    add("graph_file", "truncated", graph(3, 2, True)[:-3])
    for target in ("prim_file", "obj_file", "obj_list", "map_file", "graph_file"):
        letter = {"prim_file": b"p", "obj_file": b"o", "obj_list": b"l", "map_file": b"m", "graph_file": b"g"}[target]
        for name, data in seeds[target].items():
            if len(data) < 2048:
                add("dump", target + "-" + name, letter + data)
    add("text_inputs", "edge-map-limit", b"m1\n181 181\n")
    add("text_inputs", "edge-obj-cycle", b"d4\n- 1 2\n+ 0 3\nS 1\nB 1\nNULL\n")
    add("text_inputs", "edge-obj-ocopy", b"d3\n+ 1 2\nO 1 1\nO 1 2\nNULL\n")
    add("text_inputs", "edge-light-crlf", b"l0.1 0.1 0.1\r\n1\r\n+1e3 -2.5E2 0\r\n1 1 1\r\n")
    add("text_inputs", "edge-model-c",
        b'C/* Module: Model */\n#include <stdio.h>\nvoid main(void);\nvoid main(void)\n{\n'
        b'  Message("Building model of scene");\n  InitFiles();\n  OpenFiles();\n'
        b'  AddObj("d1.txt");\n  AddToObjList(0x1);\n  CopyObj("O1", "O2", "c1.txt"); // copy\n'
        b'  AddMap("Map1.txt");\n  CloseFiles();\n  if (!MemoryEmpty())\n  {\n    FreeAll();\n'
        b'    Error("main(): Number of Mallocs != Number of Frees");\n  }\n}\n\x1a')
    add("text_inputs", "edge-reader-words", b"r+150 1.5e2 -32768 32768 nan inf 0x10 word\t\n1.5x")

    # The inputs of tests/prime/unit/legacy_io/fuzz_regressions_test.cpp that are small.
    add("dump", "regression-shared-subtrees",
        b"o" + obj_file([("+", i + 1, i + 1) for i in range(40)] + [("P", 0, 0)]))
    add("text_inputs", "regression-two-signs", b"l+-5 +-2.5 +5\n1\n")
    good = [
        ("obj/H1.txt", b"0.1 0.2 0.3 0.4 0.5 0.999 2 2 1.5\n"),
        ("obj/D1.txt", b"3\n- 1 2\nB 1\nS 1\nNULL\n"),
        ("prim/B1.txt", b"B\n100 100 100\n0 0 0\n0 0 0\n0 0 0\n1 1 1 1 1 1 1 1 1 1 1 1\n0\n"),
        ("prim/S1.txt", b"S\n60 60 60\n50 50 0\n0 0 0\n0 0 0\n1 1\n0\n"),
        ("obj/Copy/c.txt", b"1 1 1\n0 0 0\n0 0 0\n0 0 0\n"),
        ("prim/A1.txt", b"1 1 1\n0 0 0\n0 0 0\n0 0 0\n"),
        ("light/light.txt", b"0.2 0.2 0.2\n0\n"),
    ]
    for dest in ("Copy", "List", "D1.txt"):
        add("model_builder", "regression-copyobj-" + dest.replace(".", "-"),
            bundle([("Model.txt", b"AddObj d1.txt\nAddToObjList 1\nCopyObj O1 %s c.txt\n" % dest.encode())] + good))
    add("model_builder", "regression-long-name", bundle([("Model.txt", b"AddMap " + b"a" * 300 + b".txt\n")] + good))
    chain = b"300\n" + b"".join(b"+ %d %d\n" % (i + 1, i + 1) for i in range(299)) + b"S 1\nNULL\n"
    copies = b"112\n+ 1 1\n" + b"O 1 1\n" * 111 + b"NULL\n"  # 112 + 111*299 > 32767 entries
    add("model_builder", "regression-o-entry-limit",
        b"L" + bundle([("Model.txt", b"AddObj d1.txt\nAddObj d2.txt\n"), ("obj/D1.txt", chain),
                       ("obj/H2.txt", good[0][1]), ("obj/D2.txt", copies)] + good[:1] + good[3:]))

    total = 0
    for target, files in sorted(seeds.items()):
        d = os.path.join(CORPUS, target)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        for name, data in sorted(files.items()):
            with open(os.path.join(d, name), "wb") as f:
                f.write(data)
            total += len(data)
        print("%-14s %3d seeds" % (target, len(files)))
    print("total %d bytes" % total)
    assert total < 200 * 1024


if __name__ == "__main__":
    main()
