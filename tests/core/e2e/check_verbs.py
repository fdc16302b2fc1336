#!/usr/bin/env python3
"""One tool for three systems: every shared verb, for every system, by its own name.

For each system's scene (PRIME's default scene directory, a Malone and a CGL
scene file) and each verb, runs the real `prime` and checks:
  - `prime VERB SCENE --help` says `prime VERB` (never a hidden name such as
    cgl-trace), lists the flags every system shares with that verb, and says
    whose options follow;
  - `prime --help` lists no hidden command, and nothing else names one;
  - `trace` writes --png, --true-color-png and --png-8514 for every system,
    each a PNG, and accepts --threads, -q and --max-depth;
  - `probe SCENE --pixel X Y --json` prints one JSON object with the shared
    keys (scene, where, events [{depth, event, data}], color, rays), and the
    text form names the same pixel;
  - `--format NAME` names the system and is refused for a name that is none.
With --table, prints the verbs x systems x shared flags table (Markdown).

Run: check_verbs.py PRIME_EXE REPO_ROOT [--table]
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

PRIME, ROOT = sys.argv[1], sys.argv[2]
TABLE = "--table" in sys.argv

SCENES = {
    "prime": os.path.join(ROOT, "scenes/prime/default"),
    "malone": os.path.join(ROOT, "scenes/malone/doc-sphere.mal"),
    "cgl": os.path.join(ROOT, "scenes/cgl/ball.cgl"),
}
TITLES = {"prime": "PRIME (1991)", "malone": "Malone's ray tracer (1995)",
          "cgl": "the Waterloo CGL package (1985)"}
SHARED = {
    "trace": ["--format", "--png", "--true-color-png", "--png-8514", "--quantize", "--threads",
              "-q", "--no-window", "--zoom", "--fullscreen", "--scale", "--pace", "--no-wait"],
    "probe": ["--format", "--pixel", "--json"],
    "bench": ["--format"],
    "walk": ["--format", "--threads", "--bench", "--pin", "--pivot", "--camera-file", "--no-window",
             "--zoom", "--fullscreen", "--eye", "--look-at", "--up", "--fov", "--size", "--camera"],
    "export-pov": ["--format"],
}
# Each system's own flags that must keep one name across systems.
ALSO = {"trace": ["--max-depth"], "probe": ["--max-depth"]}
HIDDEN = ["malone-trace", "malone-probe", "malone-bench", "malone-export-pov", "cgl-trace",
          "cgl-probe", "cgl-bench", "cgl-export-pov", "cgl-export", "cgl-view"]

failures = []
table = {}


def run(args, cwd=None):
    env = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="")
    return subprocess.run([PRIME] + args, capture_output=True, text=True, cwd=cwd, env=env)


def check(ok, what):
    if not ok:
        failures.append(what)
    return ok


top = run(["--help"])
check(top.returncode == 0, "prime --help exits 0")
for h in HIDDEN:
    check(h not in top.stdout, f"prime --help names the hidden command {h}")
    r = run([h, SCENES["cgl"]])
    check(r.returncode == 2 and "unknown command" in r.stderr,
          f"prime {h} is no command any more (exit {r.returncode}: {r.stderr.strip()})")

with tempfile.TemporaryDirectory() as tmp:
    scratch = os.path.join(tmp, "default")
    shutil.copytree(SCENES["prime"], scratch)
    SCENES["prime"] = scratch
    for system, scene in SCENES.items():
        for verb, flags in SHARED.items():
            r = run([verb, scene, "--help"])
            ok = check(r.returncode == 0, f"{verb} {system} --help exits 0: {r.stderr}")
            text = r.stdout
            ok &= check(f"Usage: {PRIME} {verb} " in text or f"prime {verb} " in text,
                        f"{verb} {system} --help names 'prime {verb}'")
            ok &= check(TITLES[system] in text, f"{verb} {system} --help names {TITLES[system]}")
            for h in HIDDEN:
                ok &= check(h not in text, f"{verb} {system} --help names {h}")
            cells = {}
            for f in flags + ALSO.get(verb, []):
                present = (" " + f + " ") in text or (" " + f + ",") in text or \
                          ("," + f + " ") in text or text.rstrip().endswith(f)
                cells[f] = present
                check(present, f"{verb} {system} --help lists {f}")
            table[(verb, system)] = cells

        # trace writes every PNG flag, each a PNG.
        out = {k: os.path.join(tmp, f"{system}-{k}.png") for k in ("png", "true", "8514")}
        args = ["trace", scene, "--png", out["png"], "--true-color-png", out["true"],
                "--png-8514", out["8514"], "--threads", "1", "-q", "--max-depth", "3"]
        if system == "prime":
            args += ["--model", "--out", os.path.join(tmp, "graph")]
        r = run(args)
        if check(r.returncode == 0, f"trace {system} with the shared flags: {r.stderr}"):
            for k, path in out.items():
                ok = os.path.exists(path) and open(path, "rb").read(8) == b"\x89PNG\r\n\x1a\n"
                check(ok, f"trace {system} wrote {k} as a PNG")

        # probe --pixel --json, one schema.
        r = run(["probe", scene, "--pixel", "3", "4", "--json"])
        if check(r.returncode == 0, f"probe {system} --pixel --json: {r.stderr}"):
            try:
                doc = json.loads(r.stdout)
            except json.JSONDecodeError as e:
                check(False, f"probe {system} --json is JSON: {e}")
                doc = {}
            for key in ("scene", "where", "events", "color", "rays"):
                check(key in doc, f"probe {system} --json has '{key}'")
            check(doc.get("where", "").startswith("pixel 3 4"),
                  f"probe {system} --json: where is pixel 3 4, not {doc.get('where')}")
            for e in doc.get("events", []):
                check(set(e) == {"depth", "event", "data"},
                      f"probe {system} event keys {sorted(e)}")
            if system != "prime":
                check(system in doc, f"probe {system} --json keeps its own fields in '{system}'")
        r = run(["probe", scene, "--pixel", "3", "4"])
        check(r.returncode == 0 and r.stdout.strip(), f"probe {system} --pixel text")

        r = run(["trace", scene, "--format", system, "--help"])
        check(r.returncode == 0 and TITLES[system] in r.stdout, f"--format {system} names it")
        r = run(["trace", scene, "--format", "nosuch"])
        check(r.returncode == 2, f"--format nosuch refused for {system} (exit {r.returncode})")

# walk takes one ray per pixel: its help lists no sampling option, which it
# would only refuse.
r = run(["walk", os.path.join(ROOT, "scenes/prime/default"), "--help"])
listed = [line.split()[0] for line in r.stdout.splitlines() if line.startswith("  -")]
check(r.returncode == 0 and not {"--samples", "--jitter", "--adaptive", "--statistical"} & set(listed),
      f"walk --help lists no sampling option: {listed}")

# A file named on the command line that is not a scene of the system --format
# names: the system's own reader says so (Malone's numbers read as CGL).
r = run(["trace", SCENES["malone"], "--format", "cgl", "--no-window"])
check(r.returncode != 0, "a Malone scene with --format cgl is refused by CGL's reader")

if TABLE:
    verbs = list(SHARED)
    print("| verb | shared flag | PRIME | Malone | CGL |")
    print("|---|---|---|---|---|")
    for verb in verbs:
        for f in SHARED[verb] + ALSO.get(verb, []):
            cells = ["yes" if table.get((verb, s), {}).get(f) else "NO" for s in SCENES]
            print(f"| {verb} | `{f}` | " + " | ".join(cells) + " |")

for f in failures:
    print("FAIL: " + f)
checked = sum(len(c) for c in table.values())
print(f"{len(failures)} failed; {checked} verb x system x flag cells checked")
sys.exit(1 if failures else 0)
