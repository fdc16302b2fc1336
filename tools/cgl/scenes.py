#!/usr/bin/env python3
"""Writes the Waterloo CGL scenes of scenes/cgl/ that this port adds or
reconstructs (M. A. J. Sweeney, "The Waterloo CGL Ray Tracing Package",
University of Waterloo CS-85-35, 1985). A CGL scene file spells every colour
as a 33-sample spectrum (380-700 nm every 10 nm), which nobody should type by
hand; this script writes them from a few smooth curves and says in each file
what every record is. The verbatim copies of the document's own examples
(doc-*.cgl) are typed in by hand and not written here.

With --check it writes nothing and fails when a committed scene differs from
what it makes (ctest tools.cgl_scenes_are_generated).

    python3 tools/cgl/scenes.py [--check]
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.normpath(os.path.join(HERE, "..", "..", "scenes", "cgl"))

# CIE D6500, as the document prints it for its ambience and its light
# (Appendix 1, sections 10 and 11): "the colour of daylight on an overcast day".
D6500 = [50.0, 54.6, 82.8, 91.5, 93.4, 86.7, 104.9, 117.0, 117.8, 114.9,
         115.9, 108.8, 109.4, 107.8, 104.8, 107.7, 104.4, 104.0, 100.0, 96.3,
         95.8, 88.7, 90.0, 89.6, 87.7, 83.3, 83.7, 80.0, 80.2, 82.3,
         78.3, 69.7, 71.6]
# The document's "flat blue" Lambert surface (Appendix 1, section 8).
FLAT_BLUE = [0.1273, 0.1337, 0.1432, 0.1528, 0.1751, 0.1910, 0.2069, 0.2228, 0.2133, 0.1910,
             0.1751, 0.1655, 0.1528, 0.1369, 0.1210, 0.1050, 0.0955, 0.0796, 0.0637, 0.0573,
             0.0477, 0.0392, 0.0382, 0.0350, 0.0350, 0.0382, 0.0382, 0.0414, 0.0446, 0.0955,
             0.1273, 0.1592, 0.2228]
WAVELENGTHS = [380 + 10 * i for i in range(33)]


def flat(v):
    return [v] * 33


def bump(centre, width, peak, base=0.02):
    """A smooth reflectance: `base` everywhere, rising to `peak` around `centre` nm."""
    return [base + (peak - base) * math.exp(-0.5 * ((w - centre) / width) ** 2) for w in WAVELENGTHS]


def edge(at, width, high, low=0.02):
    """Low below `at` nm, high above it (reds, oranges, yellows)."""
    return [low + (high - low) / (1 + math.exp(-(w - at) / width)) for w in WAVELENGTHS]


RED = edge(600, 12, 0.55)
ORANGE = edge(570, 12, 0.6)
GREEN = bump(530, 35, 0.45)
PALE = flat(0.5)
GREY = flat(0.3)
DARK = flat(0.06)  # the checkerboard's "dark gray" perfect reflector


def num(v):
    s = "%.4f" % v
    return "0.0000" if s == "-0.0000" else s


def vector(values, fmt=num):
    """A colour-vector as the manual writes it: 3 lines of 10 numbers and one of 3."""
    assert len(values) == 33
    return [" ".join(fmt(v) for v in values[i:i + 10]) for i in range(0, 33, 10)]


def spd(v):
    return ("%.1f" % v)


# Cook-Torrance (section 9.9), as the package's `cook` utility and this port's
# `prime cook` (src/cgl/cook.cpp) make a surface: from a normal reflectance R,
# the effective index n = (1 + sqrt R)/(1 - sqrt R), k = 0, the unpolarised
# Fresnel reflectance at 66 angles theta_j = j * 90/65 degrees (CGL-Q102), and
# the normal-colour-vector D = R / pi (CGL-Q106).
def fresnel(n, c):
    if n == 1.0:
        return 0.0
    g = math.sqrt(n * n + c * c - 1.0)
    a = (g - c) / (g + c)
    b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0)
    return 0.5 * a * a * (1.0 + b * b)


def fresnel_table(reflectance):
    n = [(1.0 + math.sqrt(r)) / (1.0 - math.sqrt(r)) for r in reflectance]
    return [[fresnel(nk, math.cos(j * (math.pi / 2.0) / 65)) for nk in n] for j in range(66)]


# The document's copper (Appendix 1 section 8): its first (and second) Fresnel
# vector, which is pi times its printed normal-colour-vector at every
# wavelength (CGL-Q106): the normal reflectance the table was made from.
COPPER = [0.0700, 0.0760, 0.0820, 0.0880, 0.0950, 0.1060, 0.1170, 0.1280, 0.1400, 0.1560,
          0.1720, 0.1890, 0.2050, 0.2200, 0.2350, 0.2500, 0.2650, 0.3000, 0.3350, 0.4120,
          0.4900, 0.5520, 0.6150, 0.6420, 0.6700, 0.6830, 0.6970, 0.7110, 0.7250, 0.7320,
          0.7400, 0.7480, 0.7550]
# Gold's normal reflectance R = ((n - 1)^2 + k^2)/((n + 1)^2 + k^2) from the
# optical constants of a 117 nm evaporated gold film at 380-700 nm every 10 nm
# (D. I. Yakubovsky et al., "Optical constants and structural properties of
# thin gold films", Optics Express 25, 25574-25587, 2017; as tabulated in the
# public-domain refractiveindex.info database), rounded to 4 places.
GOLD = [0.3914, 0.3950, 0.3972, 0.3982, 0.3984, 0.3979, 0.3967, 0.3942, 0.3921, 0.3922,
        0.4004, 0.4307, 0.4977, 0.5894, 0.6830, 0.7498, 0.7997, 0.8368, 0.8653, 0.8873,
        0.9045, 0.9175, 0.9289, 0.9380, 0.9455, 0.9519, 0.9573, 0.9618, 0.9657, 0.9689,
        0.9715, 0.9734, 0.9749]


class Scene:
    def __init__(self, title, about):
        self.title, self.about = title, about
        self.program, self.display, self.vertices = [], [], []
        self.surfaces, self.lights, self.nodes = [], [], []
        self.ambience = None

    # Program and display parameters: "count keyword args".
    def param(self, text):
        self.program.append(text)

    def view(self, text):
        self.display.append(text)

    def vertex(self, x, y, z):
        self.vertices.append((x, y, z))
        return len(self.vertices)

    def lambert(self, comment, colour, diffuse=7.0, reflect=0.0, refract=0.0, index=0.0):
        n = len(self.surfaces) + 1
        self.surfaces.append(["* surface %d: %s" % (n, comment),
                              "%d lambert normal %s %s %s" % (n, reflect, refract, index),
                              "%s" % diffuse] + vector(colour))
        return n

    def phong(self, comment, colour, diffuse, specular, exponent, reflect=0.0, refract=0.0,
              index=0.0):
        n = len(self.surfaces) + 1
        self.surfaces.append(["* surface %d: %s" % (n, comment),
                              "%d phong normal %s %s %s" % (n, reflect, refract, index),
                              "%s %s %s" % (diffuse, specular, exponent)] + vector(colour))
        return n

    def textured(self, comment, model, texture, umod=1.0, vmod=1.0, diffuse=7.0, specular=None,
                 exponent=None, reflect=0.0, refract=0.0, index=0.0):
        n = len(self.surfaces) + 1
        coefficients = "%s" % diffuse if model == "lambert" else "%s %s %s" % (
            diffuse, specular, exponent)
        self.surfaces.append(["* surface %d: %s" % (n, comment),
                              "%d %s textured %s %s %s" % (n, model, reflect, refract, index),
                              coefficients, "%s %s %s" % (texture, umod, vmod)])
        return n

    def cook(self, comment, reflectance, diffuse, specular, m, reflect=0.0, refract=0.0,
             index=0.0):
        """A cook surface as `prime cook` writes it (the numbers "%.4f")."""
        n = len(self.surfaces) + 1
        self.surfaces.append(["* surface %d: %s" % (n, comment),
                              "%d cook normal %s %s %s" % (n, reflect, refract, index),
                              "%s" % diffuse, "* normal reflectance vs wavelength (R / pi)"] +
                             vector([r / math.pi for r in reflectance]) +
                             ["%s %s" % (specular, m),
                              "* fresnel reflectance vs wavelength & angle (66 angles, "
                              "j * 90/65 degrees, j = 0..65)"] +
                             sum((vector(row) for row in fresnel_table(reflectance)), []))
        return n

    def ambient(self, ka, colour=D6500):
        self.ambience = ["%.5f" % ka] + vector(colour, spd)

    def light(self, kind, x, y, z, dw, colour=D6500, comment=None):
        n = len(self.lights) + 1
        self.lights.append(([("* " + comment)] if comment else []) +
                           ["%d %s %s %s %s %s" % (n, kind, x, y, z, dw)] + vector(colour, spd))
        return n

    def node(self, text, comment=None):
        """`text` is the record after its count: "sphere 00 02 1 0.0 0.0 0.0 0.1 x y"."""
        n = len(self.nodes) + 1
        self.nodes.append(([("* " + comment)] if comment else []) + ["%d %s" % (n, text)])
        return n

    def spline(self, surface, nu, endu, nv, endv, divisions, overlap, controls, comment=None,
               right=0):
        """A spline node: `controls` is nv groups (lists) of nu (x, y, z) triples."""
        n = len(self.nodes) + 1
        lines = ([("* " + comment)] if comment else []) + [
            "%d spline 00 %02d %d %d %s %d %s %d %s" % (n, right, surface, nu, endu, nv, endv,
                                                        divisions, overlap)]
        assert len(controls) == nv and all(len(g) == nu for g in controls)
        for group in controls:
            lines += ["%d %s %s %s" % ((i + 1,) + tuple(num(c) for c in v))
                      for i, v in enumerate(group)]
        self.nodes.append(lines)
        return n

    def text(self):
        out = ["* scene: " + self.title]
        out += ["* " + l if l else "*" for l in self.about]
        out += ["* written by tools/cgl/scenes.py; the format: docs/cgl/scene-format.md",
                "%d %d %d %d %d %d 1" % (len(self.program), len(self.display), len(self.vertices),
                                        len(self.surfaces), len(self.lights), len(self.nodes))]
        out.append("* program parameters")
        out += ["%d %s" % (i + 1, p) for i, p in enumerate(self.program)]
        out.append("* display parameters")
        out += ["%d %s" % (i + 1, p) for i, p in enumerate(self.display)]
        out.append("* vertices")
        out += ["%d %s %s %s" % ((i + 1,) + tuple("%+.4f" % c for c in v))
                for i, v in enumerate(self.vertices)]
        for s in self.surfaces:
            out += s
        out.append("* ambience")
        out += self.ambience
        out.append("* lights")
        for l in self.lights:
            out += l
        out.append("* scene nodes (count keyword down right ...; 00 = none)")
        for n in self.nodes:
            out += n
        return "\n".join(out) + "\n"


def checkerboard():
    s = Scene("a mirror ball above a green/blue checkerboard",
              ["The document's example scene (Sweeney 1985, section 1.3, Figure 2, and",
               "Appendix 1 section 2, Figure 59; Figure 5: 18:30 minutes on the VAX 11/780),",
               "as Figure 59 prints it with its OCR damage repaired: the comment marks, the",
               "count of surface 1 ('l'), the reflector's colour-vector (printed 0.06 0.06 0.06,",
               "read as 0.06 at every sample: 'a dark gray material'), and the texture, which",
               "is lost: textures/checkerboard.rle is the port's green/blue checkerboard.",
               "The verbatim copies are doc-figure59.cgl and doc-figure2.cgl."])
    for p in ["depth 3", "shadows", "xleft 31", "xright 480", "yhigh 286"]:
        s.param(p)
    s.view("eye 0.0 0.0 3.5")
    s.view("sight towards 0.0 0.0 0.0")
    for v in [(-1, 0, -1), (-1, 0, 1), (1, 0, 1), (1, 0, -1)]:
        s.vertex(*v)
    s.textured("the checkerboard texture map", "lambert", "textures/checkerboard.rle", 1.0, 1.0)
    s.phong("a perfect reflector", DARK, 0.0, 2.5, 25.0, reflect=1.0)
    s.ambient(0.0005)
    s.light("infinity", 0.6, 1.0, 0.6, 0.0006,
            comment="to the upper left and behind the observer: sunlight on a cloudy day")
    s.node("rotate 02 04 x -22.0")
    s.node("translate 03 00 0.0 -0.8 0.0")
    s.node("polygon 00 00 1 4 4 3 2 1")
    s.node("sphere 00 00 2 0.3 -0.18 0.0 0.16 x y")
    return s


def ball():
    s = Scene("one ball, for the anti-aliasing levels of Figure 45",
              ["Figure 45 shows 'five identical balls', rendered without anti-aliasing and at",
               "aalevel 1, 2, 4 and 8 with aathreshold 40.0 (1:01, 1:06, 1:33, 1:55 and 2:33",
               "minutes on the VAX). The ball itself is not described: this is a shiny red",
               "Phong ball, its picture tightly bounded as the manual advises. Render it with",
               "prime trace ball.cgl --aalevel 0|1|2|4|8."])
    for p in ["xleft 196", "xright 316", "ylow 196", "yhigh 316", "aathreshold 40.0"]:
        s.param(p)
    s.phong("shiny red", RED, 7.0, 3.0, 25.0)
    s.ambient(0.0005)
    s.light("infinity", 1.0, 1.0, 1.0, 0.0006)
    s.node("sphere 00 00 1 0.0 0.0 0.0 0.3 x y")
    return s


def illumination():
    s = Scene("the illumination models and the ambience function (Figure 46)",
              ["Figure 46: 'The three illumination models supported, and our ambience",
               "function' (9:04 minutes). Left to right: Lambert, Phong, Cook-Torrance, and a",
               "sphere lit by the ambience term alone, k_a((N.V) + 0.5) I_a pi D (section 9.6;",
               "its k_d is 0 and no light reaches it). All four share the document's 'flat",
               "blue' colour-vector (Appendix 1 section 8); the Cook-Torrance sphere's Fresnel",
               "table is made, as the package's cook utility made one, from the normal",
               "reflectance pi times flat blue (k_d 1.0, k_s 1.0, m 0.3: the document's",
               "copper's k_s and m)."])
    for p in ["ylow 150", "yhigh 362", "aalevel 2"]:
        s.param(p)
    s.lambert("flat blue, Lambert (the document's example)", FLAT_BLUE, 7.0)
    s.phong("flat blue, Phong", FLAT_BLUE, 7.0, 3.0, 25.0)
    s.lambert("flat blue, ambience only (diffuse 0)", FLAT_BLUE, 0.0)
    s.cook("flat blue, Cook-Torrance", [math.pi * d for d in FLAT_BLUE], 1.0, 1.0, 0.3)
    s.ambient(0.001)
    s.light("infinity", 1.0, 1.0, 1.0, 0.0006)
    # World +x is on the viewer's left (left-handed, z out of the screen).
    s.node("sphere 00 02 1 0.9 0.0 0.0 0.26 x y", "Lambert, on the left")
    s.node("sphere 00 03 2 0.3 0.0 0.0 0.26 x y", "Phong")
    s.node("sphere 00 04 4 -0.3 0.0 0.0 0.26 x y", "Cook-Torrance")
    s.node("sphere 00 00 3 -0.9 0.0 0.0 0.26 x y", "ambience only, on the right")
    return s


def metals():
    s = Scene("Cook-Torrance metals beside Phong and Lambert, on a floor they reflect",
              ["Section 9.9: 'although the Cook-Torrance model accurately predicts the surface",
               "shading of metal, ... true metallic appearance comes as much from the coherence",
               "of reflections as from the shading' (Figure 54). Back row, left to right: a",
               "Lambert and a Phong sphere in the copper's colour, and Cook-Torrance copper",
               "that reflects nothing; front row: Cook-Torrance copper and gold, reflect 0.8.",
               "The copper is Appendix 1 section 8's (specular 1.0, m 0.3, reflect 0.8, diffuse",
               "0.0) with all 66 Fresnel vectors made from the normal reflectance its printed",
               "first vector gives (the document prints only 2 of the 66; CGL-Q106). The gold's",
               "normal reflectance comes from measured optical constants (tools/cgl/scenes.py",
               "names them). The floor is the port's green/blue checkerboard texture."])
    for p in ["depth 3", "shadows", "ylow 96", "yhigh 416", "aalevel 2"]:
        s.param(p)
    s.view("eye 0.0 0.9 3.5")
    s.view("sight towards 0.0 -0.1 0.0")
    for v in [(-2, -0.35, -2), (-2, -0.35, 2), (2, -0.35, 2), (2, -0.35, -2)]:
        s.vertex(*v)
    s.textured("the floor: the checkerboard texture, 2 x 2 repeats", "lambert",
               "textures/checkerboard.rle", 2.0, 2.0)
    s.lambert("copper-coloured Lambert", COPPER, 3.0)
    s.phong("copper-coloured Phong", COPPER, 3.0, 3.0, 25.0)
    s.cook("Cook-Torrance copper, reflecting nothing", COPPER, 0.0, 1.0, 0.3)
    s.cook("reflective copper (Appendix 1 section 8)", COPPER, 0.0, 1.0, 0.3, reflect=0.8)
    s.cook("reflective gold", GOLD, 0.0, 1.0, 0.3, reflect=0.8)
    s.ambient(0.0005)
    s.light("infinity", 0.6, 1.0, 0.6, 0.0006)
    # World +x is on the viewer's left.
    s.node("polygon 00 02 1 4 4 3 2 1", "the floor, y = -0.35")
    s.node("sphere 00 03 2 0.8 0.0 -0.6 0.35 x y", "back left: Lambert")
    s.node("sphere 00 04 3 0.0 0.0 -0.6 0.35 x y", "back middle: Phong")
    s.node("sphere 00 05 4 -0.8 0.0 -0.6 0.35 x y", "back right: Cook-Torrance, no reflection")
    s.node("sphere 00 06 5 0.42 0.0 0.35 0.35 x y", "front left: reflective copper")
    s.node("sphere 00 00 6 -0.42 0.0 0.35 0.35 x y", "front right: reflective gold")
    return s


CUBE = [(-1, 1, 1), (1, 1, 1), (1, 1, -1), (1, -1, -1), (1, -1, 1), (-1, -1, 1), (-1, -1, -1),
        (-1, 1, -1)]
FACES = ["2 3 4 5", "6 7 8 1", "1 8 3 2", "5 4 7 6", "1 2 5 6", "8 7 4 3"]


def nine_cubes(boxed):
    about = ["The DAG example of Appendix 1 section 12 (the line drawing of Figure 62):",
             "'9 cubes formed by (1) three translations in y of (2) three translations in x",
             "of (3) a rotation about the x axis of (4) a scaling (about the origin) of (5)",
             "the six polygons defining a cube.' The printed listing is scrambled and gives",
             "neither the vertices nor the surface: the node parameters are read in the",
             "printed order (docs/cgl/scenes.md), the 8 vertices are the corners of the cube",
             "(-1..1) that make the six printed faces closed rectangles, the surface is the",
             "port's. Nodes 4 and 7 are shared: 6 faces x 9 paths = 54 polygons."]
    if boxed:
        about += ["This copy follows the manual's hint: a super box around the six polygons of",
                  "each cube (node 8 'box'), so a ray tests 9 boxes, not 54 polygons."]
    s = Scene("nine cubes" + (", each in a super box" if boxed else ""), about)
    s.param("shadows")
    for v in CUBE:
        s.vertex(*v)
    s.phong("orange plastic", ORANGE, 7.0, 2.0, 20.0)
    s.ambient(0.0005)
    s.light("infinity", 1.0, 1.0, 1.0, 0.0006)
    s.node("translate 04 02 +0.0 -0.7 +0.0")
    s.node("translate 04 03 +0.0 +0.0 +0.0")
    s.node("translate 04 00 +0.0 +0.7 +0.0")
    s.node("translate 07 05 -0.7 +0.0 +0.0")
    s.node("translate 07 06 +0.0 +0.0 +0.0")
    s.node("translate 07 00 +0.7 +0.0 +0.0")
    s.node("rotate 08 00 x -22.0")
    first = 9 if not boxed else 10
    if boxed:
        s.node("scale 09 00 0.2 0.2 0.2")
        s.node("box 10 00", "the super box around one cube's six faces")
    else:
        s.node("scale 09 00 0.2 0.2 0.2")
    for i, f in enumerate(FACES):
        nxt = first + i + 1 if i + 1 < len(FACES) else 0
        s.node("polygon 00 %02d 1 4 %s" % (nxt, f))
    return s


def primitives():
    s = Scene("every node type",
              ["The port's scene with every kind of scene node of Appendix 1 section 13:",
               "translate, scale, rotate, sphere, cylinder, polygon (a triangle and",
               "rectangles), box and dummy; shadows from a light at infinity and one in the",
               "scene. A cylinder is open (no end caps, section 3), and no scale changes the",
               "radius of a sphere or a cylinder: the scaled group on the left keeps its",
               "spheres' size while their centres move closer."])
    s.param("shadows")
    s.param("aalevel 2")
    s.view("eye 0.0 0.6 3.5")
    s.view("sight towards 0.0 -0.1 0.0")
    floor = [s.vertex(x, -0.5, z) for x, z in [(-1.4, -1.4), (-1.4, 1.2), (1.4, 1.2), (1.4, -1.4)]]
    tri = [s.vertex(*v) for v in [(-1.0, -0.5, -0.6), (-0.4, -0.5, -0.9), (-0.75, 0.4, -0.8)]]
    cyl = [s.vertex(0.0, -0.5, 0.0), s.vertex(0.0, 0.3, 0.0)]
    back = [s.vertex(*v) for v in [(-1.4, -0.5, -1.4), (-1.4, 0.9, -1.4), (1.4, 0.9, -1.4),
                                   (1.4, -0.5, -1.4)]]
    s.lambert("pale floor", PALE, 5.0)
    s.phong("red plastic", RED, 7.0, 2.5, 30.0)
    s.phong("green plastic", GREEN, 7.0, 2.5, 30.0)
    s.lambert("flat blue (the document's)", FLAT_BLUE, 7.0)
    s.ambient(0.0005)
    s.light("infinity", 1.0, 1.5, 1.2, 0.0005)
    s.light("inscene", -0.6, 0.9, 0.8, 0.0004, comment="a light in the scene, left front")
    s.node("dummy 00 02 this dummy does nothing but follow its right link", "the root")
    s.node("polygon 00 03 1 4 %d %d %d %d" % tuple(floor), "the floor (a rectangle)")
    s.node("polygon 00 04 4 4 %d %d %d %d" % tuple(back), "the back wall")
    s.node("box 05 00", "a super box around the rest")
    s.node("polygon 00 06 3 3 %d %d %d" % tuple(tri), "a green triangle, back right (world -x)")
    s.node("cylinder 00 07 2 0.12 %d %d" % tuple(cyl), "an open red cylinder in the middle")
    s.node("translate 08 09 0.0 0.42 0.0", "a ball on top of the cylinder")
    s.node("sphere 00 00 3 0.0 0.0 0.0 0.12 x y")
    s.node("translate 10 00 0.75 -0.2 0.35", "a rotated, scaled group on the left (world +x is on the left)")
    s.node("rotate 11 00 y 30.0")
    s.node("scale 12 00 1.0 0.5 1.0")
    s.node("sphere 00 13 2 0.0 -0.3 0.0 0.15 x y", "centre scaled to y = -0.15: radius kept")
    s.node("sphere 00 00 3 0.35 -0.3 0.0 0.1 x y")
    return s


def glass():
    s = Scene("glass and a mirror over the checkerboard",
              ["Reflection and refraction (sections 8.4 and 8.5): a transparent Phong sphere",
               "(refract 0.8, index 1.2, as the manual's 'transparent phong' example) and a",
               "perfect reflector over the checkerboard, depth 4, shadows on: the transparent",
               "sphere casts no shadow (section 9.3), the mirror does."])
    for p in ["depth 4", "shadows", "aalevel 2"]:
        s.param(p)
    s.view("eye 0.0 0.4 3.5")
    s.view("sight towards 0.0 -0.3 0.0")
    for v in [(-1.5, 0, -1.5), (-1.5, 0, 1.5), (1.5, 0, 1.5), (1.5, 0, -1.5)]:
        s.vertex(*v)
    s.textured("the checkerboard", "lambert", "textures/checkerboard.rle", 3.0, 3.0)
    s.phong("clear glass, slightly green", bump(530, 80, 0.1, 0.04), 1.0, 3.0, 60.0, refract=0.8,
            index=1.2)
    s.phong("a perfect reflector", DARK, 0.0, 2.5, 25.0, reflect=1.0)
    s.ambient(0.0005)
    s.light("infinity", 0.6, 1.0, 0.6, 0.0006)
    s.node("translate 02 03 0.0 -0.6 0.0")
    s.node("polygon 00 00 1 4 4 3 2 1", "the floor")
    s.node("sphere 00 04 2 -0.25 -0.25 0.45 0.35 x y", "glass, front right")
    s.node("sphere 00 00 3 0.55 -0.3 -0.4 0.3 x y", "mirror, back left")
    return s


def textures():
    s = Scene("texture maps on a sphere, a cylinder and polygons",
              ["Texture mapping (section 10) on the three primitives that take it: a",
               "sphere (u from the named axes, section 2.3), an open cylinder (u along the",
               "axis, section 3.3) and a rectangle and a triangle (section 4.3), with umod and",
               "vmod repeats and the `last` keyword (the previous texture again). The textures",
               "are the port's (textures/checkerboard.rle and textures/rings.rle); the",
               "document's checkerboard and mandrill are lost."])
    s.param("shadows")
    s.param("aalevel 2")
    s.view("eye 0.0 0.5 3.5")
    s.view("sight towards 0.0 0.0 0.0")
    floor = [s.vertex(x, -0.5, z) for x, z in [(-1.3, -1.3), (-1.3, 1.0), (1.3, 1.0), (1.3, -1.3)]]
    cyl = [s.vertex(0.55, -0.5, -0.2), s.vertex(0.55, 0.45, -0.2)]
    tri = [s.vertex(*v) for v in [(-0.2, -0.5, -1.0), (0.3, 0.6, -1.0), (0.8, -0.5, -1.0)]]
    s.textured("checkerboard floor, 2 x 2 repeats", "lambert", "textures/checkerboard.rle", 2.0, 2.0)
    s.textured("rings on a Phong sphere", "phong", "textures/rings.rle", 1.0, 1.0, 7.0, 2.0, 30.0)
    s.textured("the previous texture again ('last'), 3 x 1", "lambert", "last", 3.0, 1.0)
    s.textured("checkerboard, once", "lambert", "textures/checkerboard.rle", 1.0, 1.0)
    s.ambient(0.0005)
    s.light("infinity", 1.0, 1.2, 1.0, 0.0006)
    s.node("polygon 00 02 1 4 %d %d %d %d" % tuple(floor), "the floor")
    s.node("sphere 00 03 2 -0.5 -0.1 0.2 0.38 x y", "a textured sphere, right (world -x)")
    s.node("cylinder 00 04 3 0.25 %d %d" % tuple(cyl), "a textured open cylinder, left (world +x)")
    s.node("polygon 00 00 4 3 %d %d %d" % tuple(tri), "a textured triangle at the back")
    return s


def lamp():
    s = Scene("a light inside a glass globe",
              ["Section 9.3 and Appendix 1 section 11: lights are never visible, and",
               "transparent objects cast no shadows, 'so that a light source can be put",
               "inside a transparent sphere'. An in-scene light sits inside a glass globe",
               "over a floor; an opaque ball and a cylinder cast shadows away from it, and the",
               "shadow rays stop at the light's distance."])
    for p in ["shadows", "depth 2", "aalevel 2"]:
        s.param(p)
    s.view("eye 0.0 1.0 3.5")
    s.view("sight towards 0.0 -0.2 0.0")
    floor = [s.vertex(x, -0.5, z) for x, z in [(-1.5, -1.5), (-1.5, 1.5), (1.5, 1.5), (1.5, -1.5)]]
    cyl = [s.vertex(0.6, -0.5, 0.3), s.vertex(0.6, 0.1, 0.3)]
    s.lambert("pale floor", PALE, 6.0)
    s.phong("a faint glass globe", flat(0.05), 0.5, 2.0, 40.0, refract=0.9, index=1.05)
    s.phong("red plastic", RED, 7.0, 2.0, 30.0)
    s.ambient(0.0003)
    s.light("inscene", 0.0, 0.35, 0.0, 0.0007, comment="the lamp, inside the globe")
    s.node("polygon 00 02 1 4 %d %d %d %d" % tuple(floor), "the floor")
    s.node("sphere 00 03 2 0.0 0.35 0.0 0.15 x y", "the globe around the lamp")
    s.node("sphere 00 04 3 -0.55 -0.25 0.35 0.25 x y", "an opaque ball")
    s.node("cylinder 00 00 3 0.1 %d %d" % tuple(cyl), "an open cylinder")
    return s


EARTH = edge(570, 45, 0.34, 0.13)  # a warm brown-grey rock
FIGURES = {0: (13, "the original triangle", "13:49"), 1: (14, "after 1 subdivision", "22:45"),
           2: (15, "after 2 subdivisions", "26:37"), 4: (16, "after 4 subdivisions", "32:53"),
           5: (17, "after 5 subdivisions", "36:39"), 9: (18, "after 10 subdivisions", "54:06"),
           10: (18, "after 10 subdivisions", "54:06")}


def fractal(divisions):
    figure, caption, vax = FIGURES[divisions]
    about = ["Figure %d of section 5: '%s' (%s minutes on the VAX 11/780)." % (
        figure, caption[0].upper() + caption[1:], vax),
             "The fractal triangle of section 5.2: the standard triangle (-1, 0, 1),",
             "(1, 0, 1), (0, 0, -1), its y perturbed at each subdivision by",
             "s 2^(-h l) G; h 0.9 ('0.9 for mountains'), offset 0.0, the seed of the",
             "document's example node (Appendix 1 section 13) and a free perimeter (a",
             "constrained one leaves 1 subdivision flat: its only midpoints are on the",
             "perimeter). The document's random generator is lost, so this is the port's",
             "surface for these numbers, not the document's (docs/cgl/rendering.md). Lit",
             "from the left and low, with shadows, so that the relief shows."]
    if divisions == 0:
        about += ["The reader takes 1-10 divisions: the plain triangle is a polygon on",
                  "the standard triangle's three vertices (what 0 divisions would make)."]
    if divisions == 9:
        about += ["Figure 18 claims 10 subdivisions, above the manual's range of 1-9: this",
                  "is 9, the manual's largest; fractal-10.cgl is the figure's 10."]
    if divisions == 10:
        about += ["10 is above the manual's range of 1-9; the port's reader takes it with a",
                  "warning (CGL-Q9) for this figure: 1,048,576 facets, 143 MB."]
    name = "the fractal triangle, %d subdivision%s" % (divisions, "" if divisions == 1 else "s")
    s = Scene(name if divisions else "the fractal triangle before any subdivision", about)
    for p in ["shadows", "aalevel 2", "ylow 64", "yhigh 400"]:
        s.param(p)
    s.view("eye 0.0 1.3 3.4")
    s.view("sight towards 0.0 0.05 -0.1")
    s.lambert("a warm brown-grey rock", EARTH, 7.0)
    s.ambient(0.0005)
    s.light("infinity", 1.0, 0.45, 0.25, 0.0007,
            comment="low, from the left (world +x is on the viewer's left)")
    if divisions == 0:
        tri = [s.vertex(*v) for v in [(-1.0, 0.0, 1.0), (1.0, 0.0, 1.0), (0.0, 0.0, -1.0)]]
        s.node("polygon 00 00 1 3 %d %d %d" % tuple(tri), "the standard triangle itself")
    else:
        s.node("fractal 00 00 1 %d 0.9 0.0 9772 free" % divisions)
    return s


def fractal_hills():
    s = Scene("texture-mapped fractal hills over water",
              ["Section 5.3 and 5.7: 'A fractal is texture mapped as if it were a",
               "triangle, temporarily ignoring the y coordinate', a claim of the package",
               "shown in Figure 57 (Crater Lake: 'the hills are texture mapped fractals').",
               "Two hills with the manual's values for rolling hills (h 1.3, offset 0.5,",
               "free perimeter), the port's checkerboard 3 x 3 and 2 x 2 times (the",
               "document's textures are lost), and a reflecting lake (a rectangle)."])
    for p in ["shadows", "depth 1", "aalevel 2", "ylow 80", "yhigh 400"]:
        s.param(p)
    s.view("eye 0.0 1.2 3.4")
    s.view("sight towards 0.0 0.0 0.0")
    lake = [s.vertex(x, -0.05, z) for x, z in [(-2.5, -2.5), (-2.5, 2.0), (2.5, 2.0), (2.5, -2.5)]]
    s.textured("the checkerboard, 3 x 3", "lambert", "textures/checkerboard.rle", 3.0, 3.0, 9.0)
    s.phong("blue water, half a mirror", bump(470, 60, 0.15, 0.04), 2.0, 2.0, 40.0, reflect=0.5)
    s.textured("the checkerboard again, 2 x 2", "lambert", "last", 2.0, 2.0, 9.0)
    s.ambient(0.0008)
    s.light("infinity", 0.8, 0.9, 0.5, 0.0009)
    s.node("polygon 00 02 2 4 %d %d %d %d" % tuple(lake), "the lake")
    s.node("translate 03 05 0.55 0.0 -0.45", "the left hill (world +x is on the left)")
    s.node("scale 04 00 1.0 1.4 1.0")
    s.node("fractal 00 00 1 6 1.3 0.5 9772 free")
    s.node("translate 06 00 -0.7 0.0 -0.2", "the right hill, turned")
    s.node("rotate 07 00 y 150.0")
    s.node("scale 08 00 0.9 1.2 0.9")
    s.node("fractal 00 00 3 5 1.3 0.5 1985 free")
    return s


BUMP_CAPTIONS = {
    "single": "Figure 28, 'a patch as it would result from single boundary vertices' (2:55 minutes)",
    "double": "Figure 29, 'a patch as it would result from double boundary vertices' (26:49 minutes)",
    "triple": "Figure 30, 'a patch as it would result from triple boundary vertices' (32:26 "
              "minutes), the 'bump' of Tables 3 and 6",
}


def spline_bump(end):
    s = Scene("the bump patch, %s boundary vertices" % end,
              ["Sweeney 1985, section 6.4, " + BUMP_CAPTIONS[end] + ".",
               "The bump: a 4 x 4 control graph, flat but for its four middle vertices raised,",
               "which the program extends to 8 x 8 = 64 vertices by tripling its boundary rows and",
               "columns (Table 3: 64 original, 1849 refined vertices at divisions 8); overlap 0.5.",
               "The control vertices are not printed: these are the port's. The end condition",
               "only restricts the parameter range (6.4.1)."])
    s.view("eye 0.0 2.2 2.6")
    s.view("sight towards 0.0 0.05 0.0")
    s.phong("a pale green plastic", GREEN, 7.0, 2.0, 20.0)
    s.ambient(0.0005)
    s.light("infinity", 0.5, 1.0, 0.7, 0.0006)
    xs = [-1.0, -1.0 / 3.0, 1.0 / 3.0, 1.0]
    controls = [[(x, 1.2 if (0 < i < 3 and 0 < j < 3) else 0.0, z) for i, x in enumerate(xs)]
                for j, z in enumerate(xs)]
    s.spline(1, 4, end, 4, end, 8, 0.5, controls)
    return s


def spline_donut():
    s = Scene("the closed spline donut of Figure 31",
              ["Sweeney 1985, section 6.4, Figure 31, 'a closed spline donut' (93:04 minutes):",
               "'U(i,j) = U(i,j+5), U(i,j) = U(i+5,j) for an arrangement of 81 control vertices':",
               "a 5 x 5 graph, closed both ways, which the program wraps to 9 x 9 = 81 (Table 3:",
               "9801 refined vertices at divisions 16); overlap 0.75 (Table 6). The vertices are",
               "the port's: two regular pentagons, scaled so the surface has radii 0.6 and 0.25."])
    s.view("eye 0.0 2.0 2.4")
    s.view("sight towards 0.0 0.0 0.0")
    s.phong("an orange glaze", ORANGE, 7.0, 2.5, 30.0)
    s.ambient(0.0005)
    s.light("infinity", 0.6, 1.0, 0.5, 0.0006)
    shrink = (4.0 + 2.0 * math.cos(2.0 * math.pi / 5.0)) / 6.0  # a closed pentagon's spline radius
    big, small = 0.6 / shrink, 0.25 / shrink
    controls = []
    for j in range(5):  # v: around the tube
        phi = 2.0 * math.pi * j / 5.0
        group = []
        for i in range(5):  # u: around the hole
            theta = 2.0 * math.pi * i / 5.0
            rr = big + small * math.cos(phi)
            group.append((rr * math.cos(theta), small * math.sin(phi), rr * math.sin(theta)))
        controls.append(group)
    s.spline(1, 5, "closed", 5, "closed", 16, 0.75, controls)
    return s


VASE_PROFILE = [(0.0, 0.16), (0.12, 0.30), (0.32, 0.34), (0.55, 0.16), (0.72, 0.10), (0.85, 0.17)]


def spline_vases():
    s = Scene("three spline vases with too little overlap (Figure 55)",
              ["Sweeney 1985, section 13, Figure 55: 'three spline vases with insufficient",
               "overlap; from highest to lowest overlap 0.4, 0.3, 0.2' (90:32 minutes); section",
               "6.5: 'an overlap less than 0.5 produces an interesting effect'. Each vase is",
               "closed in u (8 vertices around) and double in v (6 rings), like the tube of",
               "Appendix 1 section 13; divisions 2. The holes are the point of the picture. The",
               "CGL camera's right is up x sight, so +x is on the left: 0.4 is at x = +0.85."])
    s.view("eye 0.0 0.9 3.2")
    s.view("sight towards 0.0 0.4 0.0")
    s.phong("a blue glaze", FLAT_BLUE, 7.0, 2.0, 25.0)
    s.ambient(0.0005)
    s.light("infinity", 0.4, 1.0, 0.8, 0.0006)
    for k, (x, overlap) in enumerate([(0.85, 0.4), (0.0, 0.3), (-0.85, 0.2)]):
        controls = []
        for y, r in VASE_PROFILE:
            group = []
            for i in range(8):
                a = 2.0 * math.pi * (i + 0.5) / 8.0
                group.append((x + r * math.cos(a), y, r * math.sin(a)))
            controls.append(group)
        s.spline(1, 8, "closed", len(VASE_PROFILE), "double", 2, overlap, controls,
                 comment="overlap %s" % overlap, right=k + 2 if k < 2 else 0)
    return s


def mask_controls(count, nose, eye_width, eye_height, mouth):
    """A face as a height field over [-1, 1]^2 (the port's stand-in for the lost digitized
    Halloween mask of Figure 53): count x count control vertices, z the height."""
    def height(x, y):
        face = max(0.0, 1.0 - (x / 0.8) ** 2 - (y / 1.0) ** 2)
        z = 0.45 * math.sqrt(face)
        z += 0.18 * math.exp(-((x / nose) ** 2) - ((y + 0.05) / 0.3) ** 2)  # nose
        for ex in (-0.3, 0.3):
            z -= 0.12 * math.exp(-(((x - ex) / eye_width) ** 2) - ((y - 0.25) / eye_height) ** 2)
        z -= 0.08 * math.exp(-((x / 0.3) ** 2) - ((y + 0.5) / mouth) ** 2)  # mouth
        return z

    last = count - 1
    return [[(-1.0 + 2.0 * i / last, 1.0 - 2.0 * j / last,
              height(-1.0 + 2.0 * i / last, 1.0 - 2.0 * j / last)) for i in range(count)]
            for j in range(count)]


def spline_mask():
    s = Scene("a mask-sized mesh of 2,025 vertices (Tables 3 and 6)",
              ["Sweeney 1985, Tables 3 and 6, the 'mask' of Figure 53 (a Halloween mask, cut into",
               "strips and digitized: 2025 vertices, divisions 2, overlap 0.55; 49 minutes in",
               "Table 6, 72:29 in the caption). The digitized mesh is lost: this is the port's",
               "own mask, a 41 x 41 height field (extended to 45 x 45 = 2025 by tripling; Table 3:",
               "7569 refined vertices), for Table 6's measurements."])
    s.view("eye 0.0 0.0 3.0")
    s.view("sight towards 0.0 0.0 0.0")
    s.phong("copper-coloured", ORANGE, 7.0, 2.5, 30.0)
    s.ambient(0.0005)
    s.light("infinity", 0.5, 0.7, 1.0, 0.0006)

    controls = mask_controls(41, 0.09, 0.14, 0.09, 0.06)
    s.spline(1, 41, "triple", 41, "triple", 2, 0.55, controls)
    return s


# Stainless steel seen at normal incidence: about 0.55, a little higher in the red (iron's
# n = 2.9, k = 3.0 at 550 nm give ((n-1)^2 + k^2)/((n+1)^2 + k^2) = 0.52; the port's smooth
# ramp from 0.50 at 380 nm to 0.60 at 700 nm, for the gallery's steel).
STEEL = [0.50 + 0.10 * i / 32.0 for i in range(33)]


def gallery():
    s = Scene("a gallery room in the spirit of Figure 54",
              ["Figure 54: 'View of a gallery room with a spline mask. The mask is rendered in",
               "copper, and the sphere and cylinder are stainless steel. The copper and steel",
               "were achieved using the Cook-Torrance illumination model. The sphere and mask",
               "reflect each other' (about 35 hours on the VAX). The room, the mask and the",
               "pictures are lost: this is the port's own room. A copper B-spline mask (the",
               "port's 21 x 21 height field, divisions 2, overlap 0.55) hangs on the left; a",
               "steel sphere and a steel cylinder stand on the right, and they and the mask",
               "reflect each other (depth 3); a picture (the port's rings texture) hangs on the",
               "back wall, on a checkerboard floor. The copper is Appendix 1 section 8's, the",
               "steel a smooth normal reflectance of about 0.55 (tools/cgl/scenes.py)."])
    for p in ["depth 3", "shadows", "aalevel 2"]:
        s.param(p)
    s.view("eye 0.0 0.15 3.2")
    s.view("sight towards 0.0 -0.05 0.0")
    floor = [s.vertex(x, -0.5, z) for x, z in [(-1.6, -1.3), (-1.6, 2.0), (1.6, 2.0), (1.6, -1.3)]]
    wall = [s.vertex(*v) for v in [(-1.6, -0.5, -1.3), (-1.6, 1.3, -1.3), (1.6, 1.3, -1.3),
                                   (1.6, -0.5, -1.3)]]
    picture = [s.vertex(*v) for v in [(-0.45, 0.1, -1.29), (-0.45, 0.75, -1.29),
                                      (0.45, 0.75, -1.29), (0.45, 0.1, -1.29)]]
    cyl = [s.vertex(-0.15, -0.5, -0.55), s.vertex(-0.15, 0.55, -0.55)]
    s.textured("the floor: the checkerboard, 3 x 3", "lambert", "textures/checkerboard.rle", 3.0,
               3.0, 5.0)
    s.lambert("the walls: pale", PALE, 4.0)
    s.textured("the picture: the port's rings", "lambert", "textures/rings.rle", 1.0, 1.0, 6.0)
    s.cook("the mask: reflective copper (Appendix 1 section 8)", COPPER, 0.0, 1.0, 0.3,
           reflect=0.8)
    s.cook("stainless steel", STEEL, 0.0, 1.0, 0.2, reflect=0.7)
    s.ambient(0.0006)
    s.light("infinity", 0.4, 1.0, 0.9, 0.0005)
    s.light("inscene", -0.2, 1.1, 1.2, 0.0003, comment="a lamp above the viewer")
    s.node("polygon 00 02 1 4 %d %d %d %d" % tuple(floor), "the floor")
    s.node("polygon 00 03 2 4 %d %d %d %d" % tuple(wall), "the back wall")
    s.node("polygon 00 04 3 4 %d %d %d %d" % tuple(picture), "the picture on it")
    s.node("sphere 00 05 5 -0.55 -0.22 0.25 0.28 x y", "the steel sphere, right front")
    s.node("cylinder 00 06 5 0.13 %d %d" % tuple(cyl), "the steel cylinder, right back")
    s.node("translate 07 00 0.55 0.12 -0.25", "the mask, left (world +x is on the left)")
    s.node("rotate 08 00 y -25.0", "turned towards the sphere")
    s.node("scale 09 00 0.42 0.52 0.42")

    controls = mask_controls(21, 0.12, 0.16, 0.11, 0.08)
    s.spline(4, 21, "triple", 21, "triple", 2, 0.55, controls, comment="the copper mask")
    return s


SCENES = {
    "checkerboard.cgl": checkerboard,
    "ball.cgl": ball,
    "illumination-models.cgl": illumination,
    "metals.cgl": metals,
    "nine-cubes.cgl": lambda: nine_cubes(False),
    "nine-cubes-boxed.cgl": lambda: nine_cubes(True),
    "primitives.cgl": primitives,
    "glass.cgl": glass,
    "textures.cgl": textures,
    "lamp.cgl": lamp,
    "fractal-0.cgl": lambda: fractal(0),
    "fractal-1.cgl": lambda: fractal(1),
    "fractal-2.cgl": lambda: fractal(2),
    "fractal-4.cgl": lambda: fractal(4),
    "fractal-5.cgl": lambda: fractal(5),
    "fractal-9.cgl": lambda: fractal(9),
    "fractal-10.cgl": lambda: fractal(10),
    "fractal-hills.cgl": fractal_hills,
    "spline-bump-single.cgl": lambda: spline_bump("single"),
    "spline-bump-double.cgl": lambda: spline_bump("double"),
    "spline-bump-triple.cgl": lambda: spline_bump("triple"),
    "spline-donut.cgl": spline_donut,
    "spline-vases.cgl": spline_vases,
    "spline-mask.cgl": spline_mask,
    "gallery.cgl": gallery,
}


def main(argv):
    check = "--check" in argv[1:]
    stale = []
    for name, make in SCENES.items():
        text = make().text()
        path = os.path.join(OUT, name)
        if check:
            try:
                with open(path) as f:
                    if f.read() != text:
                        stale.append(name)
            except OSError:
                stale.append(name)
        else:
            os.makedirs(OUT, exist_ok=True)
            with open(path, "w") as f:
                f.write(text)
    if stale:
        print("scenes/cgl: not what tools/cgl/scenes.py writes: " + ", ".join(stale) +
              " (run python3 tools/cgl/scenes.py)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
