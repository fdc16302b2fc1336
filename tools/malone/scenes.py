#!/usr/bin/env python3
"""Writes the Malone scenes of scenes/malone/: the port's own, and the
document's examples of section 2, each verbatim inside a small scene (a
viewer, a light, a surface) of this port's. The document's complete scene of
section 1.2 (doc-scene.mal) is typed in by hand, verbatim, and not written
here.

Malone's input language has no comments (the strict reading), so the scenes
are written by this script, which says what each number is. With --check it
writes nothing and fails when a committed scene differs from what it makes
(ctest tools.malone_scenes_are_generated).

    python3 tools/malone/scenes.py [--check]
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.normpath(os.path.join(HERE, "..", "..", "scenes", "malone"))


def num(v):
    if isinstance(v, int):
        return str(v)
    s = "%.6f" % v
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def line(*vals):
    return " ".join(num(v) for v in vals)


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    l = math.sqrt(sum(x * x for x in a))
    return [x / l for x in a]


class Scene:
    def __init__(self):
        self.lines = []

    def viewer(self, eye, look, fov, xres, yres, up=(0, 1, 0)):
        """102: x and y perpendicular to the view, square pixels, `fov` degrees across."""
        w = norm(sub(look, eye))
        right = norm(cross(w, up))
        upv = cross(right, w)
        t = math.tan(math.radians(fov) / 2)
        self.lines += ["102", line(*eye), line(*look), line(*[c * t for c in right]),
                       line(*[c * t * yres / xres for c in upv]), line(xres, yres)]

    def light(self, pos, rgb, falloff=True):
        self.lines += ["101" if falloff else "104", line(*pos), line(*rgb)]

    def sampled(self, samples, centre, radius, rgb):
        self.lines += ["105", line(samples), line(*centre), line(radius), line(*rgb)]

    def ambient(self, rgb):
        self.lines += ["103", line(*rgb)]

    @staticmethod
    def surf(colour, ks=0.0, ke=1, kd=1.0, kt=0.0, index=0.0):
        return ["100", line(*colour), line(ks, ke), line(kd, kt, index)]

    def default(self, surface):
        self.lines += ["106"] + surface

    def prim(self, pid, rows, surface):
        self.lines += [str(pid)] + [line(*r) for r in rows] + (surface if surface else ["107"])

    def text(self):
        return "\n".join(self.lines) + "\n"


def floor(s, y=0.0, colour=(0.8, 0.8, 0.8)):
    s.prim(2, [[y], [0, 1, 0]], Scene.surf(colour, 0.1, 10, 0.9))


def primitives():
    s = Scene()
    s.viewer([0, 7, 16], [0, 1.2, 0], 50, 512, 384)
    s.light([-6, 12, 10], [160, 160, 160])
    s.light([8, 9, 4], [60, 60, 70])
    s.ambient([0.08, 0.08, 0.08])
    floor(s)
    s.prim(1, [[1.0], [-5, 1, -2]], Scene.surf([0.9, 0.2, 0.2], 0.5, 30, 0.8))  # sphere
    s.prim(3, [[-2, 1.2, -3], [0, 0.3, 1], [1.1]], Scene.surf([0.2, 0.5, 0.9], 0.3, 20, 0.8))  # disk
    s.prim(4, [[0.6, 1.3, -3], [0, 0.3, 1], [1.1], [0.5]], Scene.surf([0.9, 0.8, 0.2], 0.3, 20, 0.8))  # annulus
    s.prim(5, [[3, 0.01, -3], [5, 0.01, -2], [4, 2.4, -2.5]], Scene.surf([0.3, 0.9, 0.3], 0, 1, 0.9))  # triangle
    s.prim(6, [[-6.5, 0.01, 1.5], [1.6, 0, 0], [0, 1.6, 0.4]], Scene.surf([0.8, 0.4, 0.9], 0, 1, 0.9))  # parallelogram
    s.prim(7, [[-2.8, 0, 2], [1, 0, 0], [0, 1.6, 0], [0, 0, 0.6], [1], [1], [0, 1, 0]],
           Scene.surf([0.3, 0.8, 0.8], 0.5, 40, 0.8))  # affine: a stretched unit sphere
    s.prim(8, [[0.85], [0, 1], [0, 2.2, 1.5], [0, -2.2, 0]], Scene.surf([0.9, 0.6, 0.2], 0.4, 40, 0.8))  # cone
    s.prim(9, [[0.6], [0, 2.2], [2.8, 0, 1.8], [0, 1, 0]], Scene.surf([0.5, 0.7, 0.9], 0.4, 40, 0.8))  # cylinder
    s.prim(10, [[1.0], [0.35], [5.5, 0.9, 1.5], [0.2, 1, 0.6]], Scene.surf([0.9, 0.5, 0.6], 0.4, 40, 0.8))  # torus
    star = []
    for k in range(10):
        r = 1.1 if k % 2 == 0 else 0.45
        a = math.pi / 2 + k * math.pi / 5
        star.append([6.2 + r * math.cos(a), 1.6 + r * math.sin(a), -3.5])
    s.prim(11, [[10]] + star, Scene.surf([0.95, 0.85, 0.3], 0.2, 20, 0.9))  # polygon
    return s


def lights():
    s = Scene()
    s.viewer([0, 6, 14], [0, 0.8, 0], 55, 512, 320)
    floor(s)
    for i, x in enumerate([-4.5, -1.5, 1.5, 4.5]):
        s.prim(1, [[0.8], [x, 0.8, 0]], Scene.surf([0.9, 0.9, 0.9], 0.4, 30, 0.8))
    # 101: the r^-2 law. 104: the same spectrum without it. 105: a spherical
    # light of radius 0.8 sampled 16 times (soft shadows). 103: ambient.
    s.light([-3, 3, 2], [14, 4, 4])
    s.light([0, 3, 2], [0.3, 0.9, 0.3], falloff=False)
    s.sampled(16, [3, 3, 2], 0.8, [4, 4, 14])
    s.ambient([0.05, 0.05, 0.05])
    return s


def default_surface():
    s = Scene()
    s.viewer([0, 5, 12], [0, 0.5, 0], 50, 384, 256)
    s.light([-5, 10, 8], [140, 140, 140])
    s.ambient([0.1, 0.1, 0.1])
    # 106 sets the default; 107 in a surface slot uses the one current when
    # the primitive is read; a later 106 does not change it.
    s.default(Scene.surf([0.9, 0.3, 0.3], 0.3, 20, 0.8))
    floor(s)
    for x in (-4, -2):
        s.prim(1, [[0.8], [x, 0.8, 0]], None)
    s.default(Scene.surf([0.3, 0.4, 0.9], 0.3, 20, 0.8))
    for x in (0, 2):
        s.prim(1, [[0.8], [x, 0.8, 0]], None)
    s.prim(1, [[0.8], [4, 0.8, 0]], Scene.surf([0.9, 0.9, 0.3], 0.3, 20, 0.8))
    return s


def checker(s, n=8, size=1.0, y=0.0, z0=-4.0):
    a = Scene.surf([0.9, 0.9, 0.9], 0, 1, 0.9)
    b = Scene.surf([0.2, 0.2, 0.25], 0, 1, 0.9)
    for i in range(n):
        for j in range(n):
            s.prim(6, [[-n * size / 2 + i * size, y, z0 + j * size], [0, 0, size], [size, 0, 0]],
                   a if (i + j) % 2 == 0 else b)


def glass():
    s = Scene()
    s.viewer([0, 3.5, 9], [0, 1, 0], 50, 512, 384)
    s.light([-4, 9, 6], [120, 120, 120])
    s.light([5, 6, -2], [40, 40, 40])
    s.ambient([0.1, 0.1, 0.1])
    checker(s)
    # A glass sphere (index 1.5): refraction, and total internal reflection
    # where rays inside meet the surface at grazing angles.
    s.prim(1, [[1.1], [-1.3, 1.1, 0.5]], Scene.surf([1, 1, 1], 0.1, 60, 0.05, 0.85, 1.5))
    # A glass slab: light that enters its face leaves by the far face, and
    # rays inside that meet the sides beyond the critical angle (41.8 deg)
    # are reflected back (TIR): two parallelograms and four sides.
    g = Scene.surf([1, 1, 1], 0.05, 60, 0.05, 0.9, 1.5)
    x0, y0, z0, w, h, d = 0.6, 0.0, -0.4, 2.0, 2.2, 0.5
    # Outward normals: a x b points out of the box for every face.
    faces = [
        ([x0, y0, z0 + d], [w, 0, 0], [0, h, 0]),          # front (+z)
        ([x0, y0, z0], [0, h, 0], [w, 0, 0]),              # back (-z)
        ([x0, y0, z0], [0, 0, d], [0, h, 0]),              # left (-x)
        ([x0 + w, y0, z0], [0, h, 0], [0, 0, d]),          # right (+x)
        ([x0, y0 + h, z0], [0, 0, d], [w, 0, 0]),          # top (+y)
        ([x0, y0 + 0.001, z0], [w, 0, 0], [0, 0, d]),      # bottom (-y)
    ]
    for v, e1, e2 in faces:
        s.prim(6, [v, e1, e2], g)
    s.prim(1, [[0.5], [2.4, 0.5, -2.5]], Scene.surf([0.9, 0.3, 0.2], 0.3, 30, 0.8))
    return s


def mirror_corridor():
    s = Scene()
    s.viewer([0, 1.5, 4], [0, 1.2, -6], 60, 384, 256)
    s.light([0, 2.8, 0], [30, 30, 30])
    s.ambient([0.05, 0.05, 0.05])
    floor(s, 0.0, (0.6, 0.6, 0.5))
    # Two facing mirrors (k_s 0.95): every bounce a reflected ray, until the
    # depth limit (7) stops it and leaves the document's "black spots".
    m = Scene.surf([0.9, 0.9, 0.9], 0.95, 200, 0.05)
    s.prim(6, [[-1.5, 0, 3], [0, 0, -10], [0, 3, 0]], m)
    s.prim(6, [[1.5, 0, -7], [0, 0, 10], [0, 3, 0]], m)
    s.prim(1, [[0.4], [0, 0.8, -2]], Scene.surf([0.9, 0.3, 0.2], 0.3, 30, 0.8))
    s.prim(1, [[0.3], [0.6, 0.3, -4]], Scene.surf([0.2, 0.8, 0.3], 0.3, 30, 0.8))
    return s


def torus():
    s = Scene()
    s.viewer([0, 2.2, 6], [0, 0.2, 0], 45, 512, 384)
    s.light([-4, 6, 5], [90, 90, 90])
    s.light([4, 2, 3], [20, 20, 30])
    s.ambient([0.08, 0.08, 0.08])
    floor(s, -1.2)
    s.prim(10, [[1.2], [0.4], [-1.2, 0, 0], [0, 1, 0.25]], Scene.surf([0.9, 0.6, 0.2], 0.4, 50, 0.8))
    # Seen edge on: the grazing rays the quartic must not lose.
    s.prim(10, [[0.8], [0.25], [1.7, 0.3, 0], [1, 0.05, 0.2]], Scene.surf([0.3, 0.6, 0.9], 0.5, 60, 0.7))
    # A torus through the affine primitive: squashed to half its height.
    s.prim(7, [[0.3, -0.9, 1.6], [1, 0, 0], [0, 0.5, 0], [0, 0, 1], [10], [0.6], [0.2], [0, 0, 0], [0, 1, 0]],
           Scene.surf([0.8, 0.3, 0.7], 0.3, 30, 0.8))
    return s


def mesh_torus(R, r, n, m):
    """n x m quads of a torus about y, two triangles each, a x b outward."""
    def p(i, j):
        u = 2 * math.pi * i / n
        v = 2 * math.pi * j / m
        return [(R + r * math.cos(v)) * math.cos(u), r * math.sin(v), (R + r * math.cos(v)) * math.sin(u)]
    tris = []
    for i in range(n):
        for j in range(m):
            a, b, c, d = p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)
            for t in ([a, c, b], [a, d, c]):
                centre = [sum(v[k] for v in t) / 3 for k in range(3)]
                ring = norm([centre[0], 0, centre[2]])
                out = sub(centre, [ring[0] * R, 0, ring[2] * R])
                nrm = cross(sub(t[1], t[0]), sub(t[2], t[0]))
                if sum(nrm[k] * out[k] for k in range(3)) < 0:
                    t = [t[0], t[2], t[1]]
                tris.append(t)
    return tris


def mesh():
    s = Scene()
    s.viewer([0, 4.5, 7], [0, 0, 0], 45, 512, 512)
    s.light([-4, 8, 6], [110, 110, 110])
    s.light([5, 3, -2], [25, 25, 35])
    s.ambient([0.08, 0.08, 0.08])
    floor(s, -1.0)
    # 1,600 triangles (40 x 20 quads of a torus): the size of the document's
    # half-hour space shuttle, as a closed mesh. One default surface for all.
    s.default(Scene.surf([0.75, 0.75, 0.8], 0.3, 40, 0.8))
    for t in mesh_torus(2.0, 0.8, 40, 20):
        s.prim(5, t, None)
    return s


# The examples of section 2 of the document, verbatim (the triangle's and the
# parallelogram's leading spaces included), each in a small scene of its own:
# (ID, the example's lines, eye, look-at, light, surface).
DOC_EXAMPLES = {
    "doc-sphere.mal": (1, ["1", "0 0 0"], [0, 0.5, 5], [0, 0, 0], [4, 4, 6],
                       Scene.surf([0.9, 0.3, 0.2], 0.5, 20, 0.8)),
    "doc-plane.mal": (2, ["5", "0 0 1"], [3, -3, 12], [3, 4, 5], [6, 8, 10],
                      Scene.surf([0.2, 0.7, 0.3], 0, 1, 0.9)),
    "doc-disk.mal": (3, ["1 1 1", "4 3 -1", "2.5"], [13, 10, -2], [1, 1, 1], [9, 4, 6],
                     Scene.surf([0.3, 0.5, 0.9], 0.3, 30, 0.8)),
    "doc-annulus.mal": (4, ["1 1 1", "4 3 -1", "4 0.23"], [17, 13, -3], [1, 1, 1], [12, 6, 8],
                        Scene.surf([0.9, 0.8, 0.2], 0.3, 30, 0.8)),
    "doc-triangle.mal": (5, ["1 0 0", " 0 1 0", " 0 0 1"], [2, 2, 2], [0.33, 0.33, 0.33],
                         [3, 4, 2], Scene.surf([0.9, 0.4, 0.1], 0, 1, 0.9)),
    "doc-parallelogram.mal": (6, ["1 1 0", " 0 -1 0", " 0 0 -1"], [4, 0.5, -0.5], [1, 0.5, -0.5],
                              [5, 3, 1], Scene.surf([0.2, 0.5, 0.9], 0, 1, 0.9)),
    "doc-ellipsoid.mal": (7, ["", "0 0 0", "1 0 0", "0 2 0", "0 0 2", "1", "0.5", "0 0.5 0", ""],
                          [3, 1.5, 4], [0, 1, 0], [4, 4, 6],
                          Scene.surf([0.3, 0.8, 0.4], 0.5, 20, 0.8)),
    "doc-cone.mal": (8, ["0.9", "0 2", "0 2 0", "0 -5 0"], [14, 0, 14], [0, -3, 0], [8, 6, 8],
                     Scene.surf([0.8, 0.6, 0.2], 0.4, 40, 0.8)),
    "doc-cylinder.mal": (9, ["0.5", "0 10", "0 2 0", "0 -1 0"], [12, 0, 12], [0, -3, 0], [6, 6, 8],
                         Scene.surf([0.5, 0.8, 0.9], 0.4, 40, 0.8)),
}


def doc_example(pid, example, eye, look, light, surface):
    s = Scene()
    s.viewer(eye, look, 40, 256, 256)
    s.light(light, [60, 60, 60])
    s.ambient([0.1, 0.1, 0.1])
    s.lines += [str(pid)] + example + surface
    return s


SCENES = {
    "primitives.mal": primitives,
    "lights.mal": lights,
    "default-surface.mal": default_surface,
    "glass.mal": glass,
    "mirror-corridor.mal": mirror_corridor,
    "torus.mal": torus,
    "mesh-1600.mal": mesh,
}


def main():
    check = "--check" in sys.argv[1:]
    status = 0
    makers = dict(SCENES)
    for name, args in DOC_EXAMPLES.items():
        makers[name] = lambda args=args: doc_example(*args)
    for name, make in makers.items():
        text = make().text()
        path = os.path.join(OUT, name)
        if check:
            if not os.path.exists(path) or open(path).read() != text:
                print("malone scenes: %s differs from what tools/malone/scenes.py makes" % path,
                      file=sys.stderr)
                status = 1
        else:
            with open(path, "w") as f:
                f.write(text)
    return status


if __name__ == "__main__":
    sys.exit(main())
