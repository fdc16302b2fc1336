#!/usr/bin/env python3
"""The quantizer comparison of docs/prime/quantization.md, re-measurable.

Renders the shipped scenes true colour (once; kept under out/quantize/), then
quantizes each with every method of `prime quantize` (ours with and without
dithering, the listing's fixed palette, libimagequant) and prints a markdown
table: mean and max CIEDE2000, PSNR, and the median CPU time of --rounds
interleaved runs (each round runs every method once, in turn, so a busy
machine slows all of them alike).

  bench/prime/quantize_compare.py [--prime build/release/src/cli/prime] [--rounds 5]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys

PRIME_SCENES = ["default", "plate2", "plate3", "glass", "lights"]
CGL_SCENES = ["ball", "metals", "textures"]
MALONE_SCENES = ["glass", "primitives"]
METHODS = [("listing", "none"), ("popularity", "none"), ("median-cut", "none"),
           ("octree", "none"), ("popularity", "floyd-steinberg"),
           ("median-cut", "ordered"), ("median-cut", "floyd-steinberg"),
           ("octree", "ordered"), ("octree", "floyd-steinberg"),
           ("libimagequant", "none"), ("libimagequant", "floyd-steinberg")]
REPORT = re.compile(r"mean dE00 ([0-9.]+), max dE00 ([0-9.]+), PSNR ([0-9.inf]+) dB, CPU ([0-9.]+) s")


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{r.stderr}")
    return r.stdout


def render(prime, out):
    images = []
    for s in PRIME_SCENES:
        png = f"{out}/prime-{s}.png"
        extra = ["--palette", "plate3"] if s == "plate3" else []
        if not os.path.exists(png):
            run([prime, "trace", f"scenes/prime/{s}", "--model", "--no-window", "-q",
                 "--out", f"{out}/prime-{s}.graph", "--true-color-png", png] + extra)
        images.append(("PRIME " + s, png))
    for s in CGL_SCENES:
        png = f"{out}/cgl-{s}.png"
        if not os.path.exists(png):
            run([prime, "trace", f"scenes/cgl/{s}.cgl", "--no-window", "-q", "--png", png])
        images.append(("CGL " + s, png))
    for s in MALONE_SCENES:
        png = f"{out}/malone-{s}.png"
        if not os.path.exists(png):
            run([prime, "trace", f"scenes/malone/{s}.mal", "--no-window", "-q", "--png", png])
        images.append(("Malone " + s, png))
    return images


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--prime", default="build/release/src/cli/prime")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--out", default="out/quantize")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    images = render(a.prime, a.out)
    print("| scene | method | dither | mean ΔE00 | max ΔE00 | PSNR dB | CPU ms (median of %d) |" % a.rounds)
    print("|---|---|---|---:|---:|---:|---:|")
    for name, png in images:
        stem = os.path.splitext(png)[0]
        quality = {}
        times = {m: [] for m in METHODS}
        for method, dither in METHODS:
            o = run([a.prime, "quantize", png, f"{stem}-{method}-{dither}.png", "--method", method,
                     "--dither", dither, "--report", "-q"])
            quality[(method, dither)] = REPORT.search(o).groups()
        for _ in range(a.rounds):
            for method, dither in METHODS:
                o = run([a.prime, "quantize", png, f"{a.out}/timing.png", "--method", method,
                         "--dither", dither, "--report", "-q"])
                times[(method, dither)].append(float(REPORT.search(o).group(4)))
        for m in METHODS:
            mean, mx, psnr, _ = quality[m]
            print(f"| {name} | {m[0]} | {m[1]} | {float(mean):.3f} | {float(mx):.2f} | {psnr} | "
                  f"{1000 * statistics.median(times[m]):.1f} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
