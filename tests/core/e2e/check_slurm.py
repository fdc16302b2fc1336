#!/usr/bin/env python3
"""The Slurm recipes of docs/cluster.md on a real Slurm: one host, started here.

Starts munged, slurmctld and slurmd in a temporary directory
(slurm_host.py), then submits, as docs/cluster.md does,
  - bands: tools/cluster/submit.sh bands: PRIME's plate 2 cut into bands of
    rows by a job array (bands-array.sbatch), stitched by the job that
    depends on it (finish.sbatch, prime stitch);
  - film: tools/cluster/submit.sh film: a Malone scene's orbit in chunks of
    frames by a job array (film-array.sbatch), the GIF made by the job that
    depends on it (finish.sbatch, prime film);
waits for every job, checks each ended COMPLETED, and compares the stitched
picture, every frame and the GIF byte for byte with one process's render.
Then resubmits the film as written: every frame is skipped (its .render
sidecar matches), none is rendered again.

Slurm needs the Debian packages munge, slurmctld, slurmd and slurm-client
(prime.sh installs them); not root: its daemons run as the user running the
test. Without them this test FAILS, saying why: it never passes without having
run Slurm.

Run: check_slurm.py PRIME_EXE REPO_ROOT
"""
import os
import shutil
import signal
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../../support"))
sys.path.insert(0, HERE)
from prime_checks import Checks
from slurm_host import SlurmHost, unavailable

PRIME, ROOT = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
SUBMIT = os.path.join(ROOT, "tools/cluster/submit.sh")
CHECKS = Checks(PRIME)
run, check = CHECKS.run, CHECKS.check
FRAMES = 5


def submit(slurm, tmp, mode, variables, trace_args):
    """tools/cluster/submit.sh MODE TRACE_ARGS with VARIABLES; the job ids it prints."""
    env = dict(slurm.env, DISPLAY="", WAYLAND_DISPLAY="", PRIME=PRIME, **variables)
    r = slurm.run(["sh", SUBMIT, mode] + trace_args, env=env, cwd=tmp)
    if not check(r.returncode == 0, f"submit.sh {mode}: exit {r.returncode}: {r.stderr}"):
        return {}
    jobs = dict(line.split() for line in r.stdout.splitlines())
    want = {"array", "finish"} if mode == "bands" or "FILM" in variables else {"array"}
    check(set(jobs) == want, f"submit.sh {mode} printed {r.stdout!r}")
    return jobs


def same(a, b, what):
    ok = os.path.isfile(a) and os.path.isfile(b)
    if check(ok, f"{what}: {a if not os.path.isfile(a) else b} missing"):
        check(open(a, "rb").read() == open(b, "rb").read(), f"{what}: differs from one process's")


def job_logs(tmp):
    for name in sorted(os.listdir(tmp)):
        if name.startswith("slurm-") and name.endswith(".out"):
            text = open(os.path.join(tmp, name), errors="replace").read()
            print(f"--- {name}\n{text.rstrip()}")


def main():
    # A SIGTERM (ctest's timeout, a Ctrl-C'd make) unwinds through SlurmHost's teardown,
    # so no daemon outlives the test; the waits above end well before ctest's TIMEOUT.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    why = unavailable()
    if why:
        print(f"FAIL: Slurm cannot run here: {why}")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        plate2 = os.path.join(tmp, "plate2")
        shutil.copytree(os.path.join(ROOT, "scenes/prime/plate2"), plate2)
        r = run(["model", plate2])
        if not check(r.returncode == 0, f"model plate 2: {r.stderr}"):
            return CHECKS.report("Slurm recipes")
        malone = os.path.join(ROOT, "scenes/malone/glass.mal")
        path = os.path.join(tmp, "orbit.path")
        r = run(["path", malone, "--orbit", str(FRAMES), "--out", path])
        check(r.returncode == 0, f"prime path: {r.stderr}")
        # One process: the references.
        ref = os.path.join(tmp, "ref")
        os.mkdir(ref)
        band_size = ["--size", "48", "120", "-q"]
        r = run(["trace", plate2, "--out", f"{ref}/plate2.scr", "--no-window"] + band_size)
        check(r.returncode == 0, f"one process's plate 2: {r.stderr}")
        film_args = ["--size", "40", "30", "-q"]
        r = run(["trace", malone, "--camera-path", path, "--frames", f"0-{FRAMES - 1}",
                 "--out", f"{ref}/f%04d.ppm", "--png", f"{ref}/f%04d.png", "--no-window"]
                + film_args)
        check(r.returncode == 0, f"one process's frames: {r.stderr}")
        r = run(["film", f"{ref}/film.gif"] + [f"{ref}/f{i:04d}.png" for i in range(FRAMES)]
                + ["--fps", "5"])
        check(r.returncode == 0, f"one process's film: {r.stderr}")

        with SlurmHost() as slurm:
            print(f"check_slurm: node {slurm.node} idle after {slurm.ready_seconds:.1f} s")
            t0 = time.monotonic()
            out = os.path.join(tmp, "slurm")
            os.mkdir(out)
            bands = submit(slurm, tmp, "bands", {
                "SCENE": plate2, "ROWS": "120", "BANDS": "4", "PIECE": f"{out}/plate2-%d.scr",
                "STITCHED": f"{out}/plate2.scr"}, band_size)
            film = submit(slurm, tmp, "film", {
                "SCENE": malone, "CAMERA_PATH": path, "FIRST": "0", "LAST": str(FRAMES - 1),
                "PER_TASK": "2", "OUT": f"{out}/f%04d.ppm", "PNG": f"{out}/f%04d.png",
                "FILM": f"{out}/film.gif", "FPS": "5"}, film_args)
            ids = list(bands.values()) + list(film.values())
            states = slurm.wait(ids, timeout=150) if ids else {}
            took = time.monotonic() - t0
            print(f"check_slurm: bands (4 tasks) and film (3 tasks), each with its finishing "
                  f"job, done in {took:.1f} s: {sorted(states.items())}")
            check(states and all(s == "COMPLETED" for s in states.values()),
                  f"jobs not all COMPLETED: {states}")
            same(f"{out}/plate2.scr", f"{ref}/plate2.scr", "stitched plate 2")
            for i in range(FRAMES):
                for ext in (".ppm", ".png"):
                    same(f"{out}/f{i:04d}{ext}", f"{ref}/f{i:04d}{ext}", f"frame {i}{ext}")
            same(f"{out}/film.gif", f"{ref}/film.gif", "the film")
            # Resubmitted as written: every frame is done, none is rendered again.
            before = {f: os.stat(os.path.join(out, f)).st_mtime_ns for f in os.listdir(out)
                      if f.startswith("f0")}
            again = submit(slurm, tmp, "film", {
                "SCENE": malone, "CAMERA_PATH": path, "FIRST": "0", "LAST": str(FRAMES - 1),
                "PER_TASK": "2", "OUT": f"{out}/f%04d.ppm", "PNG": f"{out}/f%04d.png"},
                film_args)
            states = slurm.wait(list(again.values()), timeout=60) if again else {}
            check(states and all(s == "COMPLETED" for s in states.values()),
                  f"resubmitted film: {states}")
            after = {f: os.stat(os.path.join(out, f)).st_mtime_ns for f in before}
            check(before == after, "the resubmitted film rendered frames that were done: "
                  + ", ".join(f for f in before if before[f] != after[f]))
            if CHECKS.failures:
                job_logs(tmp)
    return CHECKS.report("Slurm recipes")


if __name__ == "__main__":
    sys.exit(main())
