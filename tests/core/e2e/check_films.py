#!/usr/bin/env python3
"""Films and bands for every system (issue 34; docs/user-guide.md, "Films and bands").

  - camera paths: `prime path --orbit` writes one whose frame 0 is the scene's
    camera; a film's frame at a key is the picture `prime trace` gives with
    that key's camera flags; a hand-written path's mistakes name the file,
    line and word;
  - frames: every output a pattern; a rerun skips the frames done (by their
    render records' hashes, not by their existence): a damaged frame and a
    frame whose record is gone are rendered again, the others skipped, and
    the result is byte-identical; other settings render everything again;
  - bands: for every system (PRIME's 1991 profile with the listing's camera,
    its thesis profile with jittered samples and soft shadows through a free
    camera, Malone, CGL with and without anti-aliasing), pieces rendered with
    different thread counts and odd boundaries stitch into the very bytes of
    one process's render, in every kind the piece was written in (graph file
    and its companion, PPM, RLE, PNG);
  - stitch refuses gaps, overlaps, pieces of another render, a piece changed
    since it was written and a file that is no piece.

Run: check_films.py PRIME_EXE REPO_ROOT
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../support"))
from prime_checks import png_text, same_pixels  # noqa (after the path)

PRIME, ROOT = sys.argv[1], sys.argv[2]
failures = []
CASES = 0


def run(args, cwd, timeout=600):
    env = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="")
    r = subprocess.run([PRIME] + args, capture_output=True, text=True, cwd=cwd, env=env,
                       timeout=timeout, errors="replace")
    r.out = r.stdout + r.stderr
    return r


def check(ok, what, r=None):
    global CASES
    CASES += 1
    if not ok:
        failures.append(what + ("" if r is None else f"\n    exit {r.returncode}: {r.out[-800:]}"))


def ok(r, what):
    check(r.returncode == 0, what, r)
    return r.returncode == 0


def same(a, b):
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def keys(path):
    """The key lines of a path file, as flag lists."""
    out = []
    for line in open(path):
        line = line.split("#")[0].split()
        if line and line[0] == "key":
            out.append(line[1:])
    return out


with tempfile.TemporaryDirectory() as tmp:
    for d in ("plate2", "plate3"):
        shutil.copytree(os.path.join(ROOT, "scenes/prime", d), os.path.join(tmp, d))
        ok(run(["model", d, "-q"], tmp), f"model {d}")
    mal = os.path.join(ROOT, "scenes/malone/doc-scene.mal")
    cgl = os.path.join(ROOT, "scenes/cgl/ball.cgl")

    # ---- camera paths --------------------------------------------------------
    systems = [("prime", os.path.join(tmp, "plate3"), ["--size", "64", "48", "--out", "F%04d.gr"], "gr"),
               ("malone", mal, ["--size", "64", "48", "--out", "F%04d.ppm"], "ppm"),
               ("cgl", cgl, ["--rle", "F%04d.rle"], "rle")]
    for name, scene, outs, ext in systems:
        d = os.path.join(tmp, "film-" + name)
        os.mkdir(d)
        r = run(["path", scene, "--orbit", "48", "-o", "orbit.txt"], d)
        ok(r, f"{name}: path --orbit")
        ks = keys(os.path.join(d, "orbit.txt"))
        check(len(ks) == 24, f"{name}: the orbit has 24 keys, not {len(ks)}")
        # 48 frames, 24 keys of a loop: frames 0, 2, 4 ... are the keys.
        r = run(["trace", scene, "--camera-path", "orbit.txt", "--frames", "0-4", "-q",
                 "--png", "F%04d.png"] + outs, d)
        ok(r, f"{name}: film frames 0-4")
        # The path's own size, as a film without --size takes it.
        size = [l.split()[1:3] for l in open(os.path.join(d, "orbit.txt")) if l.startswith("size ")]
        size = [] if "--size" in outs else ["--size"] + size[0]
        for k in (0, 4):
            r = run(["trace", scene, "-q", "--png", f"key{k}.png"] + ks[k // 2] + size +
                    [o.replace("F%04d", f"key{k}") for o in outs], d)
            ok(r, f"{name}: the key's camera as flags")
            # The same pixels; the PNGs' text differs (the frame's names its frame).
            frame_png = os.path.join(d, f"F{k:04d}.png")
            check(same_pixels(frame_png, os.path.join(d, f"key{k}.png")) and
                  same(os.path.join(d, f"F{k:04d}.{ext}"), os.path.join(d, f"key{k}.{ext}")),
                  f"{name}: film frame {k} is the picture of key {k // 2 + 1}'s camera")
            check(png_text(frame_png).get("Frame") == str(k),
                  f"{name}: frame {k}'s PNG says which frame it is: {png_text(frame_png)}")
        check(not same(os.path.join(d, "F0000.png"), os.path.join(d, "F0001.png")),
              f"{name}: the camera moves between frames")
        # Resume: frame 1 damaged, frame 3's record gone; the rest skipped.
        originals = {f: open(os.path.join(d, f), "rb").read() for f in os.listdir(d)
                     if f.startswith("F")}
        with open(os.path.join(d, "F0001.png"), "r+b") as f:
            f.seek(60)
            f.write(b"\x00\x01\x02")
        os.remove(os.path.join(d, f"F0003.{ext}.render"))
        r = run(["trace", scene, "--camera-path", "orbit.txt", "--frames", "0-4",
                 "--png", "F%04d.png"] + outs, d)
        ok(r, f"{name}: film rerun")
        skipped = sorted(int(m) for m in re.findall(r"frame (\d+) \(\d+ of \d+\): done already", r.out))
        check(skipped == [0, 2, 4], f"{name}: the rerun skips frames 0, 2, 4 only, not {skipped}", r)
        check(all(open(os.path.join(d, f), "rb").read() == b for f, b in originals.items()),
              f"{name}: the resumed film is byte-identical")
        r = run(["trace", scene, "--camera-path", "orbit.txt", "--frames", "0-1", "--threads", "1",
                 "--png", "F%04d.png"] + outs, d)
        check(r.returncode == 0 and "2 done already" in r.out,
              f"{name}: another thread count is the same render", r)
    # PRIME's --model builds the databases once, for the first frame.
    r = run(["trace", "plate3", "--model", "--camera-path", "film-prime/orbit.txt", "--frames", "0-2",
             "--size", "32", "24", "--out", "film-prime/M%04d.gr"], tmp)
    check(r.returncode == 0 and "3 rendered" in r.out, "prime: a film with --model", r)
    # Other settings: every frame again.
    d = os.path.join(tmp, "film-malone")
    r = run(["trace", mal, "--camera-path", "orbit.txt", "--frames", "0-1", "--max-depth", "2",
             "--size", "64", "48", "--out", "F%04d.ppm"], d)
    check(r.returncode == 0 and "2 rendered, 0 done already" in r.out,
          "malone: other settings render the frames again", r)
    # The default path file (where the walk's K records keys) is not replaced
    # by another orbit unless -o names it.
    own = os.path.join(d, "own.mal")
    shutil.copyfile(mal, own)
    default = os.path.join(d, "own.path")
    ok(run(["path", own, "--orbit", "12"], d), "path --orbit writes the default file")
    first = open(default).read()
    r = run(["path", own, "--orbit", "24"], d)
    check(r.returncode == 1 and f"-o {default} replaces it" in r.out and
          open(default).read() == first, "an existing default path file is kept, and said so", r)
    ok(run(["path", own, "--orbit", "24", "-o", default], d), "-o naming the default replaces it")
    check(open(default).read() != first, "-o naming the default file replaced it")
    # A hand-written path, and its mistakes.
    with open(os.path.join(d, "hand.txt"), "w") as f:
        f.write("# by hand\nframes 10\nfps 5\nkey --eye 0 2 12 --look-at 0 0.5 0\n"
                "key 1s --eye 4 2 10\nkey --eye 6 3 6 --fov 30\n")
    r = run(["trace", mal, "--camera-path", "hand.txt", "--size", "32", "24", "-q",
             "--png", "h%02d.png"], d)
    check(r.returncode == 0 and len([f for f in os.listdir(d) if re.match(r"h\d\d\.png$", f)]) == 10,
          "a hand-written path of 10 frames (a key at 1 s = frame 5)", r)
    bad = [("frames 10\nkey --eye 0 2 12\nkey 7 --eye 1 2 12\nkey 3 --eye 2 2 12\n", ":4: key 3 is at frame 3, not after key 2's frame 7: key frames must increase"),
           ("key --eye 0 2 12\nzoom 3\n", ":2:1 (token 1): directive"),
           ("key --eye 0 2 12 --fov 200\n", ":1:18 (token 6): --fov"),
           ("# nothing\n", "at least one key"),
           ("key --eye 0 0.5 0 --look-at 0 0.5 0\n", ":1:1 (token 1): key")]
    for i, (text, needle) in enumerate(bad):
        with open(os.path.join(d, f"bad{i}.txt"), "w") as f:
            f.write(text)
        r = run(["trace", mal, "--camera-path", f"bad{i}.txt", "-q", "--png", "b%d.png"], d)
        check(r.returncode != 0 and f"bad{i}.txt" in r.out and needle in r.out and
              not any(f.startswith("b") and f.endswith(".png") for f in os.listdir(d)),
              f"bad path {i}: refused naming the file and '{needle}'", r)
    for args, needle in [(["--frames", "0-3", "--png", "x.png"], "--camera-path"),
                         (["--camera-path", "orbit.txt", "--png", "x.png"], "%04d"),
                         (["--camera-path", "orbit.txt", "--eye", "1", "2", "3", "--png", "x%d.png"], "--eye"),
                         (["--camera-path", "orbit.txt", "--frames", "40-60", "--png", "x%d.png"], "0-47")]:
        r = run(["trace", mal, "-q"] + args, d)
        check(r.returncode != 0 and needle in r.out, f"trace {' '.join(args)}: refused", r)
    r = run(["trace", mal, "--camera-path", "orbit.txt", "--frames", "5", "--size", "16", "12",
             "-q", "--png", "one.png"], d)
    check(r.returncode == 0 and os.path.exists(os.path.join(d, "one.png.render")),
          "one frame may name its file without a pattern", r)
    r = run(["trace", "plate3", "--camera-path", "film-prime/orbit.txt", "-q", "--png", "x%d.png"], tmp)
    check(r.returncode != 0 and "--out PATTERN" in r.out,
          "prime: a film needs --out PATTERN (a graph file every frame)", r)

    # ---- bands -----------------------------------------------------------------
    cases = [("prime 1991, the listing's camera", "plate2", [], ["--out", "{}.gr"], [".gr", ".gr.info"],
              [(0, 300, 1), (301, 301, 2), (302, 768, 2)]),
             ("prime thesis, jittered, soft shadows, free camera", "plate3",
              ["--profile", "thesis", "--jitter", "2", "--light-radius", "40", "--size", "120", "90",
               "--look-at", "500", "400", "0"],
              ["--out", "{}.gr", "--true-color-png", "{}-tc.png"], [".gr", ".gr.info", "-tc.png"],
              [(0, 44, 2), (45, 89, 1)]),
             ("malone", mal, ["--size", "96", "70"], ["--ppm", "{}.ppm"], [".ppm"],
              [(0, 9, 2), (10, 68, 1), (69, 69, 1)]),
             ("cgl", cgl, [], ["--rle", "{}.rle", "--png-8514", "{}-8514.png"], [".rle", "-8514.png"],
              [(0, 255, 2), (256, 511, 1)]),
             ("cgl anti-aliased", cgl, ["--aalevel", "1", "--aathreshold", "0"], ["--raw", "{}.raw"],
              [".raw"], [(0, 100, 1), (101, 511, 2)])]
    for what, scene, settings, outs, exts, bands in cases:
        d = tempfile.mkdtemp(dir=tmp)
        if not os.path.isabs(scene):
            scene = os.path.join(tmp, scene)
        fill = lambda name: [o.format(name) for o in outs]
        ok(run(["trace", scene, "-q", "--png", "whole.png"] + settings + fill("whole"), d),
           f"{what}: whole")
        pieces = []
        for i, (a, b, threads) in enumerate(bands):
            r = run(["trace", scene, "-q", "--rows", f"{a}-{b}", "--threads", str(threads),
                     "--png", f"p{i}.png"] + settings + fill(f"p{i}"), d)
            ok(r, f"{what}: band {a}-{b}")
            pieces.append(f"p{i}")
        for ext in [".png"] + [e for e in exts if e != ".gr.info"]:
            r = run(["stitch", "s" + ext] + [p + ext for p in reversed(pieces)], d)
            ok(r, f"{what}: stitch {ext}")
            check(same(os.path.join(d, "s" + ext), os.path.join(d, "whole" + ext)),
                  f"{what}: the stitched {ext} is the whole render's bytes")
        if ".gr.info" in exts:
            check(same(os.path.join(d, "s.gr.info"), os.path.join(d, "whole.gr.info")),
                  f"{what}: the stitched graph file's companion is the whole render's")

    # ---- stitch refuses ----------------------------------------------------------
    d = tempfile.mkdtemp(dir=tmp)
    for name, rows, extra in [("a", "0-29", []), ("b", "30-69", []), ("c", "25-69", []),
                              ("x", "30-69", ["--max-depth", "1"])]:
        ok(run(["trace", mal, "-q", "--size", "50", "70", "--rows", rows, "--ppm", name + ".ppm"] + extra, d),
           f"piece {name}")
    for args, needle in [(["a.ppm"], "rows 30-69 of the 70 are in no piece"),
                         (["a.ppm", "c.ppm"], "both hold rows 25-29"),
                         (["a.ppm", "x.ppm"], "not a piece of the same render"),
                         (["a.ppm", "b.ppm", "./b.ppm"], "is given twice (also as b.ppm)"),
                         (["a.ppm", os.path.join(ROOT, "scenes/malone/doc-scene.mal")], "no render record")]:
        r = run(["stitch", "s.ppm"] + args, d)
        check(r.returncode != 0 and needle in r.out and not os.path.exists(os.path.join(d, "s.ppm")),
              f"stitch {' '.join(args)}: refused ('{needle}'), nothing written", r)
    with open(os.path.join(d, "b.ppm"), "r+b") as f:
        f.seek(100)
        f.write(b"\x7f")
    r = run(["stitch", "s.ppm", "a.ppm", "b.ppm"], d)
    check(r.returncode != 0 and "b.ppm" in r.out and "changed" in r.out, "a changed piece is refused", r)
    with open(os.path.join(d, "a.ppm.render"), "r+") as f:
        text = f.read().replace("xxh3 ", "xxh3 zz", 1)
        f.seek(0)
        f.write(text)
    r = run(["stitch", "s.ppm", "a.ppm", "b.ppm"], d)
    check(r.returncode != 0 and "a.ppm.render:4" in r.out and "xxh3" in r.out,
          "a damaged render record is refused naming its file, line and field", r)
    r = run(["trace", mal, "-q", "--rows", "0-9", "--quantize", "median-cut", "--png", "q.png"], d)
    check(r.returncode != 0 and "--quantize" in r.out and not os.path.exists(os.path.join(d, "q.png")),
          "--rows with --quantize is refused (the palette is the whole picture's)", r)

if failures:
    print(f"{len(failures)} of {CASES} checks failed:")
    for f in failures:
        print(" -", f)
    sys.exit(1)
print(f"films and bands: {CASES} checks passed")
