#!/usr/bin/env python3
"""`prime probe SCENE --pixel X Y --overlay OUT.png` for every system.

For a pixel of each system's scene whose ray tree has secondary rays, runs
the real `prime` and checks:
  - the overlay is written, the size of the picture `trace` writes;
  - the probed pixel is outlined (magenta) and the primary ray's hit is
    marked right there (its white square within two pixels of it): the
    system's camera projects the hit back onto the pixel it was traced for;
  - every kind of ray in the tree (`probe --json`'s events) is drawn in its
    colour: reflected cyan, transmitted orange;
  - without --pixel, --overlay is a usage error; an output in a missing
    directory is refused before anything runs.

Run: check_overlay.py PRIME_EXE REPO_ROOT
"""
import json
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../support"))
from prime_checks import Checks, png_rows, png_size

PRIME, ROOT = sys.argv[1], sys.argv[2]
CHECKS = Checks(PRIME)
run, check = CHECKS.run, CHECKS.check

WHITE, MAGENTA = b"\xff\xff\xff", b"\xff\x00\xff"
CYAN, ORANGE = bytes([0, 220, 255]), bytes([255, 160, 0])
# (scene, pixel, the picture trace writes, the ray kinds the tree holds:
# for PRIME the event's "kind", for Malone the event names, for CGL the
# rays' kinds in its own JSON).
CASES = {
    "prime": ("scenes/prime/plate3", (200, 400), (350, 769)),
    "malone": ("scenes/malone/glass.mal", (200, 150), (512, 384)),
    "cgl": ("scenes/cgl/glass.cgl", (330, 280), (512, 512)),
}


def kinds(system, doc):
    found = set()
    for e in doc.get("events", []):
        name = e["event"]
        data = e.get("data", {})
        if system == "prime" and name == "ray":
            found.add(data.get("kind"))
        elif system == "malone" and name in ("reflected", "transmitted"):
            found.add(name)
        elif system == "cgl" and name == "ray":
            found.add({"refracted": "transmitted"}.get(data.get("kind"), data.get("kind")))
    return found


with tempfile.TemporaryDirectory() as tmp:
    for system, (scene, (x, y), size) in CASES.items():
        scene = os.path.join(ROOT, scene)
        if system == "prime":
            copy = os.path.join(tmp, "plate3")
            shutil.copytree(scene, copy)
            scene = copy
            check(run(["model", scene]).returncode == 0, "model plate3")
        out = os.path.join(tmp, f"{system}.png")
        r = run(["probe", scene, "--pixel", str(x), str(y), "--overlay", out])
        if not check(r.returncode == 0 and f"wrote {out}" in r.stdout,
                     f"{system}: probe --overlay: {r.stderr.strip()}"):
            continue
        check(png_size(out) == size, f"{system}: the overlay is {png_size(out)}, not {size}")
        rows = png_rows(out)
        px = lambda cx, cy: rows[cy][3 * cx:3 * cx + 3]
        check(px(x + 3, y) == MAGENTA and px(x - 3, y) == MAGENTA and px(x, y + 3) == MAGENTA,
              f"{system}: the probed pixel is outlined")
        ring = [px(x + dx, y + dy) for dx in range(-2, 3) for dy in range(-2, 3)
                if max(abs(dx), abs(dy)) == 2]
        check(WHITE in ring, f"{system}: the primary ray's hit is marked on its own pixel")
        doc = json.loads(run(["probe", scene, "--pixel", str(x), str(y), "--json"]).stdout)
        tree = kinds(system, doc)
        colours = {bytes(rows[j][3 * i:3 * i + 3]) for j in range(size[1]) for i in range(size[0])}
        for kind, colour in (("reflected", CYAN), ("transmitted", ORANGE)):
            if kind in tree:
                check(colour in colours, f"{system}: the tree's {kind} rays are drawn")
        check(tree & {"reflected", "transmitted"}, f"{system}: the case has secondary rays: {tree}")
    r = run(["probe", os.path.join(ROOT, CASES["cgl"][0]), "--point", "3", "4",
             "--overlay", os.path.join(tmp, "x.png")])
    check(r.returncode == 2 and "--pixel" in r.stderr, f"--overlay without --pixel: {r.stderr}")
    r = run(["probe", os.path.join(ROOT, CASES["malone"][0]), "--pixel", "1", "1", "--overlay",
             os.path.join(tmp, "no", "such", "dir", "x.png")])
    check(r.returncode != 0 and "x.png" in r.stderr, f"an overlay nowhere is refused: {r.stderr}")

sys.exit(CHECKS.report("probe --overlay"))
