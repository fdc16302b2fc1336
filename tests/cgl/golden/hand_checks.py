#!/usr/bin/env python3
"""Pixels of the CGL scenes recomputed by hand from the scene files and the
document's formulas, independently of the port's code, and compared with
`prime probe` (ctest cgl.hand_checks); for fractal scenes the hit's t and
normal.

M. A. J. Sweeney, "The Waterloo CGL Ray Tracing Package", University of
Waterloo CS-85-35, 1985: the camera of Appendix 1 section 6 (screen-right =
up x sight, the ray through the pixel's integer corner, normalised), the
sphere of section 2.2, the shading of section 9 (the normal turned to the
viewer; the ambience k_a((N.V) + 0.5) I_a pi D; Lambert k_d (N.L) D I dw;
Phong + k_s (P.V)^e I dw with P = 2N - L/(N.L), normalised; Cook-Torrance
(section 9.9) I dw (N.L) (k_s S + k_d D), S = (F/pi) D_m G/((N.L)(N.V)) with
the Beckmann D_m, G, and F the scene's Fresnel row int(arccos(V.H) * 130/pi),
the port's reading CGL-Q101), the colour of
section 9.1 (X = 1360 sum c x-bar, ..., RGB = (1/15) M^-1 XYZ with the
Electrohome ECM 1301 matrix, clipped to 0..255 and truncated).

The CIE 1931 2-degree colour-matching functions at 380, 390, ..., 700 nm
are typed in below from the CIE's table (CIE 15:2004, Table T.4).

    python3 tests/cgl/golden/hand_checks.py build/release/src/cli/prime
"""
import math
import os
import re
import subprocess
import sys

CIE = [  # x-bar, y-bar, z-bar
    (0.001368, 0.000039, 0.006450), (0.004243, 0.000120, 0.020050),
    (0.014310, 0.000396, 0.067850), (0.043510, 0.001210, 0.207400),
    (0.134380, 0.004000, 0.645600), (0.283900, 0.011600, 1.385600),
    (0.348280, 0.023000, 1.747060), (0.336200, 0.038000, 1.772110),
    (0.290800, 0.060000, 1.669200), (0.195360, 0.090980, 1.287640),
    (0.095640, 0.139020, 0.812950), (0.032010, 0.208020, 0.465180),
    (0.004900, 0.323000, 0.272000), (0.009300, 0.503000, 0.158200),
    (0.063270, 0.710000, 0.078250), (0.165500, 0.862000, 0.042160),
    (0.290400, 0.954000, 0.020300), (0.433450, 0.994950, 0.008750),
    (0.594500, 0.995000, 0.003900), (0.762100, 0.952000, 0.002100),
    (0.916300, 0.870000, 0.001650), (1.026300, 0.757000, 0.001100),
    (1.062200, 0.631000, 0.000800), (1.002600, 0.503000, 0.000340),
    (0.854450, 0.381000, 0.000190), (0.642400, 0.265000, 0.000050),
    (0.447900, 0.175000, 0.000020), (0.283500, 0.107000, 0.000000),
    (0.164900, 0.061000, 0.000000), (0.087400, 0.032000, 0.000000),
    (0.046770, 0.017000, 0.000000), (0.022700, 0.008210, 0.000000),
    (0.011359, 0.004102, 0.000000),
]
M = [[0.62, 0.21, 0.15], [0.33, 0.675, 0.06], [0.05, 0.115, 0.79]]  # section 9.1


def inverse3(m):
    a, b, c = m[0]
    d, e, f = m[1]
    g, h, i = m[2]
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return [[(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det],
            [(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det],
            [(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det]]


MINV = inverse3(M)


def to_rgb(c):
    xyz = [1360 * sum(c[i] * CIE[i][k] for i in range(33)) for k in range(3)]
    out = []
    for row in MINV:
        v = sum(row[k] * xyz[k] for k in range(3)) / 15
        out.append(0 if v < 0 else 255 if v > 255 else int(v))
    return tuple(out)


def sub(a, b): return [a[i] - b[i] for i in range(3)]
def add(a, b): return [a[i] + b[i] for i in range(3)]
def mul(a, s): return [x * s for x in a]
def dot(a, b): return sum(a[i] * b[i] for i in range(3))
def norm(a): return mul(a, 1 / math.sqrt(dot(a, a)))
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def numbers(line):
    return [float(t) for t in line.split()]


def read_scene(path):
    """Just enough of Appendix 1 for these scenes: numbers, parameters, surfaces
    (untextured Lambert/Phong), ambience, lights at infinity, sphere nodes."""
    lines = [l for l in open(path) if l.strip() and not l.lstrip().startswith("*")]
    it = iter(lines)
    counts = [int(t) for t in next(it).split()[:7]]
    scene = {"eye": [0, 0, 3.5], "towards": [0, 0, 0], "up": [0, 1, 0], "dist": 2.5,
             "viewport": (2.0, 2.0), "surfaces": [], "lights": [], "spheres": []}
    for _ in range(counts[0]):
        next(it)
    for _ in range(counts[1]):
        f = next(it).split()
        if f[1] == "eye":
            scene["eye"] = [float(x) for x in f[2:5]]
        elif f[1] == "sight":
            scene["towards"] = [float(x) for x in f[3:6]]
            assert f[2] == "towards"
        elif f[1] == "up":
            scene["up"] = [float(x) for x in f[2:5]]
        elif f[1] == "dist":
            scene["dist"] = float(f[2])
        elif f[1] == "viewport":
            scene["viewport"] = (float(f[2]), float(f[3]))
    for _ in range(counts[2]):
        next(it)

    def vector():
        v = []
        while len(v) < 33:
            v += numbers(next(it))
        return v
    for _ in range(counts[3]):
        f = next(it).split()
        assert f[2] == "normal", "hand checks take untextured surfaces only"
        k = numbers(next(it))
        s = {"model": f[1], "kr": float(f[3]), "kt": float(f[4]), "kd": k[0],
             "ks": k[1] if f[1] == "phong" else 0.0, "e": k[2] if f[1] == "phong" else 0.0}
        s["D"] = vector()
        if f[1] == "cook":  # specular m, then 66 Fresnel vectors, 0 degrees first
            s["ks"], s["m"] = numbers(next(it))
            s["F"] = [vector() for _ in range(66)]
        scene["surfaces"].append(s)
    ka = float(next(it).split()[0])
    scene["ambient"] = [ka * math.pi * x for x in vector()]  # k_a pi I_a, section 9.6
    for _ in range(counts[4]):
        f = next(it).split()
        assert f[1] == "infinity"
        scene["lights"].append((norm([float(x) for x in f[2:5]]), float(f[5]), vector()))
    for _ in range(counts[5]):
        f = next(it).split()
        assert f[1] == "sphere", "hand checks take untransformed spheres only"
        scene["spheres"].append(([float(x) for x in f[5:8]], float(f[8]), int(f[4]) - 1))
    return scene


def pixel(scene, x, y):
    eye = scene["eye"]
    s = norm(sub(scene["towards"], eye))
    r = norm(cross(scene["up"], s))           # screen-right = up x sight
    u = norm(cross(s, r))                      # up, orthogonal to the sight
    h, w = scene["viewport"]
    d = norm(add(add(mul(s, scene["dist"]), mul(r, (x - 256) * w / 512)), mul(u, (y - 256) * h / 512)))
    best = None
    for c, radius, surface in scene["spheres"]:   # section 2.2
        L = sub(eye, c)
        a, b, cc = dot(d, d), 2 * dot(d, L), dot(L, L) - radius * radius
        disc = b * b - 4 * a * cc
        if disc < 0:
            continue
        t = (-b - math.sqrt(disc)) / (2 * a)
        if t <= 0:
            t = (-b + math.sqrt(disc)) / (2 * a)
        if t > 0 and (best is None or t < best[0]):
            best = (t, c, surface)
    if best is None:
        return (0, 0, 0)
    t, c, surface = best
    p = add(eye, mul(d, t))
    n = norm(sub(p, c))
    v = mul(d, -1)
    if dot(n, v) < 0:
        n = mul(n, -1)
    sf = scene["surfaces"][surface]
    nv = dot(n, v)
    z = [scene["ambient"][i] * (nv + 0.5) * sf["D"][i] for i in range(33)]
    for l, dw, intensity in scene["lights"]:
        nl = dot(n, l)
        if nl < 0:
            continue
        if sf["model"] == "cook":
            h = norm(add(v, l))
            nh, vh = dot(n, h), dot(v, h)
            m = sf["m"]
            beckmann = math.exp(-(math.tan(math.acos(nh)) / m) ** 2) / (m * m * nh ** 4)
            g = min(1, 2 * nh * nv / vh, 2 * nh * nl / vh)
            row = min(65, int(math.acos(vh) * 130 / math.pi))
            for i in range(33):
                s_lambda = sf["F"][row][i] / math.pi * beckmann * g / (nl * nv)
                z[i] += intensity[i] * nl * dw * (sf["ks"] * s_lambda + sf["kd"] * sf["D"][i])
            continue
        for i in range(33):
            z[i] += sf["kd"] * nl * sf["D"][i] * intensity[i] * dw
        if sf["model"] == "phong":
            pv = dot(norm(sub(mul(n, 2), mul(l, 1 / nl))), v)
            if pv > 0:
                for i in range(33):
                    z[i] += sf["ks"] * pv ** sf["e"] * intensity[i] * dw
    return to_rgb(z)


CHECKS = [  # scene, x, y (pixel corners; the probe traces what aalevel 0 traces)
    ("ball", 256, 256), ("ball", 230, 290), ("ball", 290, 230), ("ball", 225, 285), ("ball", 300, 256),
    ("illumination-models", 91, 256), ("illumination-models", 190, 270),
    ("illumination-models", 300, 270), ("illumination-models", 330, 240),
    ("illumination-models", 296, 272), ("illumination-models", 421, 256),
    ("illumination-models", 440, 280),
]


# Fractal surfaces (section 5), rebuilt here from the rules docs/cgl/rendering.md
# states (CGL-D120, CGL-Q120 to CGL-Q124): SplitMix64 and Marsaglia's polar
# method (with math.log: the port's own log may differ in the last bit, far
# below these tolerances), the 201 x 201 matrix indexed by round(100(x + 1)),
# midpoints perturbed by 0.5 2^(-h l)(G + offset), l = 1 first; then every
# facet tested by Cramer's rule and the nearest kept. Compared with the t and
# the facing normal that `prime probe` prints.
def fractal_surface(divisions, h, offset, seed, constrained):
    mask = (1 << 64) - 1
    state = [seed & mask]

    def splitmix():
        state[0] = (state[0] + 0x9e3779b97f4a7c15) & mask
        z = state[0]
        z = ((z ^ (z >> 30)) * 0xbf58476d1ce4e5b9) & mask
        z = ((z ^ (z >> 27)) * 0x94d049bb133111eb) & mask
        return z ^ (z >> 31)

    def uniform():
        return (splitmix() >> 11) * 2.0 ** -53 * 2.0 - 1.0
    g = []
    while len(g) < 201 * 201:
        u, v = uniform(), uniform()
        q = u * u + v * v
        if q >= 1.0 or q == 0.0:
            continue
        f = math.sqrt(-2.0 * math.log(q) / q)
        g += [u * f, v * f]
    g = [x + offset for x in g[:201 * 201]]

    def index(c):
        return min(200, max(0, int(math.floor(100.0 * (c + 1.0) + 0.5))))

    def mid(a, b, perimeter, level):
        m = [(a[i] + b[i]) * 0.5 for i in range(3)]
        if not (constrained and perimeter):
            m[1] += 0.5 * 2.0 ** (-h * level) * g[index(m[0]) * 201 + index(m[2])]
        return m
    facets = []

    def split(p0, p1, p2, e01, e12, e20, level):
        if level == divisions:
            facets.append((p0, p1, p2))
            return
        m01, m12, m20 = mid(p0, p1, e01, level + 1), mid(p1, p2, e12, level + 1), mid(p2, p0, e20, level + 1)
        split(p0, m01, m20, e01, False, e20, level + 1)
        split(m01, p1, m12, e01, e12, False, level + 1)
        split(m20, m12, p2, False, e12, e20, level + 1)
        split(m01, m12, m20, False, False, False, level + 1)
    split([-1.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 0.0, -1.0], True, True, True, 0)
    return facets


def fractal_hit(path, x, y):
    scene = {"eye": [0, 0, 3.5], "towards": [0, 0, 0], "up": [0, 1, 0], "dist": 2.5,
             "viewport": (2.0, 2.0)}
    node = None
    for line in open(path):
        f = line.split()
        if len(f) > 2 and f[1] == "eye":
            scene["eye"] = [float(v) for v in f[2:5]]
        elif len(f) > 2 and f[1] == "sight" and f[2] == "towards":
            scene["towards"] = [float(v) for v in f[3:6]]
        elif len(f) > 2 and f[1] == "fractal":
            assert node is None and f[2] == "00" and f[3] == "00", "one untransformed fractal"
            node = f
    eye = scene["eye"]
    s = norm(sub(scene["towards"], eye))
    r = norm(cross(scene["up"], s))
    u = norm(cross(s, r))
    h, w = scene["viewport"]
    d = norm(add(add(mul(s, scene["dist"]), mul(r, (x - 256) * w / 512)), mul(u, (y - 256) * h / 512)))
    best = None
    for p0, p1, p2 in fractal_surface(int(node[5]), float(node[6]), float(node[7]), int(node[8]),
                                      node[9] == "constrained"):
        a, U, V = p0, sub(p1, p0), sub(p2, p1)   # F(u, v) = A + uU + vV, 0 <= v <= u <= 1
        det = dot(U, cross(d, V))
        if det == 0:
            continue
        o = sub(eye, a)
        uu = dot(o, cross(d, V)) / det
        vv = dot(d, cross(o, U)) / det
        t = dot(V, cross(o, U)) / det
        if 0 <= uu <= 1 and 0 <= vv <= uu and t > 1e-6 and (best is None or t < best[0]):
            best = (t, norm(cross(U, V)))
    if best is None:
        return None
    t, n = best
    if dot(n, d) > 0:
        n = mul(n, -1)
    return t, n


FRACTAL_CHECKS = [("fractal-2", 256, 256), ("fractal-2", 200, 180), ("fractal-4", 300, 220),
                  ("fractal-5", 180, 200), ("fractal-5", 256, 300)]


def main(argv):
    prime = argv[1]
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
    failures = 0
    for name, x, y in CHECKS:
        path = os.path.join(root, "scenes", "cgl", name + ".cgl")
        want = pixel(read_scene(path), x, y)
        out = subprocess.run([prime, "probe", path, "--point", str(x), str(y)], capture_output=True,
                             text=True).stdout
        m = re.search(r"^RGB \(ToRGB.*\): (\d+) (\d+) (\d+)", out, re.M)
        got = tuple(int(g) for g in m.groups()) if m else None
        ok = got == want
        failures += not ok
        print("%s %s (%d, %d): by hand %s, prime probe %s" % ("ok  " if ok else "FAIL", name, x, y,
                                                            want, got))
    for name, x, y in FRACTAL_CHECKS:
        path = os.path.join(root, "scenes", "cgl", name + ".cgl")
        want = fractal_hit(path, x, y)
        out = subprocess.run([prime, "probe", path, "--point", str(x), str(y)], capture_output=True,
                             text=True).stdout
        m = re.search(r"at t = ([-\d.e+]+), point \([^)]*\), normal facing the viewer "
                      r"\(([-\d.e+]+), ([-\d.e+]+), ([-\d.e+]+)\)", out)
        got = (float(m.group(1)), [float(m.group(k)) for k in (2, 3, 4)]) if m else None
        ok = (want is None) == (got is None) and (
            want is None or (abs(want[0] - got[0]) <= 1e-7 * want[0] and
                             all(abs(want[1][k] - got[1][k]) <= 2e-6 for k in range(3))))
        failures += not ok
        print("%s %s (%d, %d): t and normal by hand %s, prime probe %s" % (
            "ok  " if ok else "FAIL", name, x, y, want, got))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
