#!/usr/bin/env python3
"""The per-quirk switches (--fix) against every shipped PRIME scene.

Models a copy of every shipped scene (but plate1, a wireframe, not ray
traced), renders it in the 1991 profile, then once per switch `prime errata
--json` lists, and checks:
  - the scenes whose true-colour picture a switch changes are exactly the
    ones `prime errata` says it shows in (so the table is measured, not
    guessed);
  - a switch changes pixels only: the graph file's size and header stay;
  - `--fix all` is every switch at once (the same bytes as naming them all);
  - `--fix` of an id without a switch, an unknown id, or with another
    profile is a usage error (exit 2) that writes nothing.
With --table, prints the measured table (scene x switch: pixels changed).

Run: check_fixes.py PRIME_EXE REPO_ROOT [--table]
"""
import json
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../support"))
from prime_checks import Checks, same_pixels

PRIME, ROOT = sys.argv[1], sys.argv[2]
TABLE = "--table" in sys.argv
CHECKS = Checks(PRIME)
run, check, failures = CHECKS.run, CHECKS.check, CHECKS.failures


def pixels(graph):
    """A graph file's pixels as 16-bit words (after its 4-byte header)."""
    data = open(graph, "rb").read()
    return data[:4], [data[i:i + 2] for i in range(4, len(data), 2)]


errata = json.loads(run(["errata", "--json", "--switches"]).stdout)
switches = [q["id"] for q in errata]
check(len(switches) >= 5, f"prime errata --switches lists the switches: {switches}")

with tempfile.TemporaryDirectory() as tmp:
    root = os.path.join(ROOT, "scenes/prime")
    scenes = sorted(n for n in os.listdir(root)
                    if os.path.isfile(os.path.join(root, n, "Model.txt")) and n != "plate1")
    changed = {s: {} for s in switches}
    for name in scenes:
        scene = os.path.join(tmp, name)
        shutil.copytree(os.path.join(root, name), scene)
        if not check(run(["model", scene]).returncode == 0, f"model {name}"):
            continue

        def render(tag, extra):
            g, p = os.path.join(tmp, f"{name}-{tag}.graph"), os.path.join(tmp, f"{name}-{tag}.png")
            r = run(["trace", scene, "--no-window", "-q", "--out", g, "--true-color-png", p] + extra)
            check(r.returncode == 0, f"trace {name} {extra}: {r.stderr}")
            return g, p

        base_g, base_p = render("base", [])
        head, base = pixels(base_g)
        for fix in switches:
            g, p = render(fix, ["--fix", fix])
            h, px = pixels(g)
            check(h == head and len(px) == len(base), f"{name} --fix {fix}: the picture's size")
            differ = sum(1 for a, b in zip(base, px) if a != b)
            png_differs = not same_pixels(p, base_p)  # the text names the --fix
            changed[fix][name] = differ if (png_differs or differ) else None
        all_g, _ = render("all", ["--fix", "all"])
        named_g, _ = render("named", ["--fix", ",".join(switches)])
        check(open(all_g, "rb").read() == open(named_g, "rb").read(),
              f"{name}: --fix all is every switch named")

    for q in errata:
        measured = [n for n in scenes if changed[q["id"]].get(n) is not None]
        listed = [s.strip() for s in q["shows"].split(",") if s.strip()]
        check(measured == listed, f"{q['id']}: prime errata says it shows in {listed}, "
                                  f"measured {measured}")
    if TABLE:
        print("| scene | " + " | ".join(switches) + " |")
        print("|---|" + "---|" * len(switches))
        for n in scenes:
            cells = []
            for s in switches:
                v = changed[s].get(n)
                cells.append("—" if v is None else f"{v}")
            print(f"| {n} | " + " | ".join(cells) + " |")

    # Usage errors write nothing.
    scene = os.path.join(tmp, scenes[0])
    out = os.path.join(tmp, "refused.png")
    for extra, why in ((["--fix", "K7"], "has no switch"), (["--fix", "K99"], "no listing quirk"),
                       (["--fix", "K18", "--profile", "modern"], "1991 profile")):
        r = run(["trace", scene, "--no-window", "-q", "--true-color-png", out] + extra)
        check(r.returncode == 2 and why in r.stderr and not os.path.exists(out),
              f"{extra} is a usage error saying '{why}': exit {r.returncode} {r.stderr.strip()}")

for f in failures:
    print("FAIL:", f)
print(f"--fix: {len(switches)} switches, {len(failures)} failure(s)")
sys.exit(1 if failures else 0)
