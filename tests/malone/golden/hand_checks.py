#!/usr/bin/env python3
"""Independent arithmetic behind the hand checks of tests/malone/golden/README.md.

Recomputes a few pixels of the Malone scenes from the numbers in the scene
files and the document's formulas (D. Malone, "A description of a simple Ray
Tracer", TCD 1995, sections 1.6-1.9), written out again here without the
port's code, and compares them with what `prime probe` reports for the same
pixel (the bytes of the golden pictures).

Usage: tests/malone/golden/hand_checks.py [PRIME_EXE]   (from the repository root)
"""
import math
import subprocess
import sys

PRIME = sys.argv[1] if len(sys.argv) > 1 else "build/release/src/cli/prime"


def sub(a, b): return [a[i] - b[i] for i in range(3)]
def add(a, b): return [a[i] + b[i] for i in range(3)]
def mul(a, s): return [x * s for x in a]
def dot(a, b): return sum(a[i] * b[i] for i in range(3))
def norm(a): return mul(a, 1 / math.sqrt(dot(a, a)))


def numbers(path):
    return [float(w) for w in open(path).read().split()]


def camera_ray(eye, look, x, y, xres, yres, X, Y):
    # v(alpha, beta) = e + (l - e)/|l - e| + alpha x + beta y (section 1.6)
    alpha = (2 * X - xres) / xres
    beta = -(2 * Y - yres) / yres
    return norm(add(add(norm(sub(look, eye)), mul(x, alpha)), mul(y, beta)))


def phong(point, n, i, light, rgb, ambient, colour, ks, ke, kd):
    """Ambient + one point light with r^-2, no shadow (checked: nothing blocks)."""
    d = n if dot(i, n) <= 0 else mul(n, -1)
    r = sub(i, mul(d, 2 * dot(i, d)))
    tl = sub(light, point)
    l = math.sqrt(dot(tl, tl))
    s = mul(tl, 1 / l)
    out = []
    for k in range(3):
        c = ambient[k] * kd * colour[k]
        if dot(d, s) > 0:
            spec = ks * dot(r, s) ** ke if dot(r, s) > 0 and ks > 0 else 0.0
            c += rgb[k] * (kd * colour[k] * dot(d, s) + spec) / (l * l)
        out.append(c)
    return out


def byte(v):
    return 0 if not v > 0 else 255 if v >= 1 else int(255 * v + 0.5)


def probe(scene, X, Y):
    out = subprocess.run([PRIME, "probe", scene, "--pixel", str(X), str(Y)], capture_output=True,
                         text=True, check=True).stdout
    last = out.strip().splitlines()[-1]
    return [int(v) for v in last.split("bytes ")[1].split(";")[0].split()]


failures = 0


def check(name, scene, X, Y, colour):
    global failures
    want = [byte(c) for c in colour]
    got = probe(scene, X, Y)
    ok = want == got
    failures += not ok
    print("%s pixel (%d, %d): %s -> bytes %s; prime %s %s" %
          (name, X, Y, ", ".join("%.6f" % c for c in colour), want, got, "OK" if ok else "DIFFERS"))


# doc-scene.mal: the document's scene (section 1.2). Centre pixel: the ray
# from (0,2,3) towards the origin meets y = 0 at the origin; light (-2,5,2),
# I = 1; surface 1 1 1 / k_s 0, k_e 30 / k_d 1; no ambient light.
v = numbers("scenes/malone/doc-scene.mal")
eye, look, x, y = v[1:4], v[4:7], v[7:10], v[10:13]
i = camera_ray(eye, look, x, y, 256, 256, 128, 128)
t = (0 - dot([0, 1, 0], eye)) / dot([0, 1, 0], i)
p = add(eye, mul(i, t))
check("doc-scene", "scenes/malone/doc-scene.mal", 128, 128,
      phong(p, [0, 1, 0], i, [-2, 5, 2], [1, 1, 1], [0, 0, 0], [1, 1, 1], 0.0, 30, 1.0))

# doc-sphere.mal: the unit sphere at the origin (the document's example),
# eye (0,0.5,5), light (4,4,6) of 60, ambient 0.1; surface 0.9 0.3 0.2 /
# k_s 0.5, k_e 20 / k_d 0.8. Three pixels: the centre, a lit one and one
# on the shadowed side.
v = numbers("scenes/malone/doc-sphere.mal")
eye, look, x, y = v[1:4], v[4:7], v[7:10], v[10:13]
for X, Y in ((128, 128), (150, 100), (100, 160)):
    i = camera_ray(eye, look, x, y, 256, 256, X, Y)
    b = dot(eye, i)
    c = dot(eye, eye) - 1
    t = -b - math.sqrt(b * b - c)  # the near root, a = 1 (section 2.2)
    p = add(eye, mul(i, t))
    check("doc-sphere", "scenes/malone/doc-sphere.mal", X, Y,
          phong(p, norm(p), i, [4, 4, 6], [60, 60, 60], [0.1, 0.1, 0.1], [0.9, 0.3, 0.2], 0.5, 20,
                0.8))

# doc-plane.mal: the plane z = 5 (the document's `5 / 0 0 1`), eye
# (3,-3,12) in front of it (the normal faces away: d = -n), light (6,8,10).
v = numbers("scenes/malone/doc-plane.mal")
eye, look, x, y = v[1:4], v[4:7], v[7:10], v[10:13]
for X, Y in ((128, 128), (40, 200)):
    i = camera_ray(eye, look, x, y, 256, 256, X, Y)
    t = (5 - dot([0, 0, 1], eye)) / dot([0, 0, 1], i)
    p = add(eye, mul(i, t))
    check("doc-plane", "scenes/malone/doc-plane.mal", X, Y,
          phong(p, [0, 0, 1], i, [6, 8, 10], [60, 60, 60], [0.1, 0.1, 0.1], [0.2, 0.7, 0.3], 0.0, 1,
                0.9))

sys.exit(1 if failures else 0)
