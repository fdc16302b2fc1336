#!/usr/bin/env python3
"""bench_web.py [--runs N]: the WebAssembly build's time per ray against the
native build's, one thread each, on shipped scenes of the three systems
(docs/web.md, "Speed"). Each run is a whole `prime trace --threads 1`; the
time is the one the program reports for the render (not node's start-up),
over the rays it reports (rays / the rays a second it prints). The runs of the two builds alternate, unpinned (under node the program's
main thread waits by spinning while the render thread works, emscripten's
way on node's main thread; pinned to one CPU, the two would share it); the table
gives the medians and their ratio. Needs build/release and build/web."""
import argparse
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NATIVE = [str(ROOT / "build" / "release" / "src" / "cli" / "prime")]
WEB = ["node", str(ROOT / "build" / "web" / "prime.js")]
SCENES = [("prime", "plate2"), ("prime", "plate3"), ("prime", "csg-operators"),
          ("prime", "plate2-thesis"), ("malone", "torus.mal"), ("malone", "glass.mal"),
          ("cgl", "spline-donut.cgl"), ("cgl", "gallery.cgl"), ("cgl", "fractal-hills.cgl")]


def one(program, system, scene, work):
    if system == "prime":
        target = work / scene
        if not target.exists():
            shutil.copytree(ROOT / "scenes" / "prime" / scene, target)
            subprocess.run(NATIVE + ["model", str(target)], check=True, capture_output=True)
        args = program + ["trace", str(target), "--out", str(work / "out.graph")]
    else:
        args = program + ["trace", str(ROOT / "scenes" / system / scene), "--out",
                          str(work / ("out.ppm" if system == "malone" else "out.rle"))]
    r = subprocess.run(args + ["--threads", "1"], capture_output=True, text=True, check=True)
    text = r.stdout + r.stderr
    # The rays and the rays a second the program reports (its own clock, to
    # the microsecond; the "in N s" it prints is rounded to hundredths).
    m = re.search(r"rays: (\d+) .*?, (\d+) rays/s", text)
    rays, per_second = int(m.group(1)), int(m.group(2))
    return rays / per_second, rays


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    options = parser.parse_args()
    work = Path(tempfile.mkdtemp(prefix="prime-bench-web-"))
    print("| system | scene | rays | native ns/ray | WebAssembly ns/ray | ratio |")
    print("|---|---|---:|---:|---:|---:|")
    ratios = []
    try:
        for system, scene in SCENES:
            times = {"native": [], "web": []}
            rays = 0
            for _ in range(options.runs):
                for side, program in (("native", NATIVE), ("web", WEB)):
                    seconds, rays = one(program, system, scene, work)
                    times[side].append(seconds)
            n, w = statistics.median(times["native"]), statistics.median(times["web"])
            ratios.append(w / n)
            print(f"| {system} | {scene} | {rays} | {n / rays * 1e9:.0f} | {w / rays * 1e9:.0f} "
                  f"| {w / n:.2f} |", flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"\nmedian ratio {statistics.median(ratios):.2f} (WebAssembly under node / native, "
          f"per ray, one thread, {options.runs} runs each)")


if __name__ == "__main__":
    sys.exit(main())
