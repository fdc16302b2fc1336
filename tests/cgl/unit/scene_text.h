// Scene files for the renderer's tests, built record by record as the
// reader would build them (legacy_io/cgl/scene_file.h), so the tests do not
// depend on the reader: small scenes with hand-computable answers, and the
// document's checkerboard (Sweeney 1985, Appendix 1, Figure 59, as
// scenes/cgl/checkerboard.cgl repairs it) with a procedural green/blue
// checkerboard standing in for the lost texture file.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "legacy_io/cgl/frame.h"
#include "legacy_io/cgl/scene_file.h"

namespace prime::cgl::test {

inline Spectrum flat(double v) {
  Spectrum s{};
  s.fill(v);
  return s;
}

// CIE D6500 as Figure 59 prints it (the ambience and the light).
inline Spectrum d6500() {
  return {50.0,  54.6,  82.8,  91.5,  93.4,  86.7,  104.9, 117.0, 117.8, 114.9, 115.9,
          108.8, 109.4, 107.8, 104.8, 107.7, 104.4, 104.0, 100.0, 96.3,  95.8,  88.7,
          90.0,  89.6,  87.7,  83.3,  83.7,  80.0,  80.2,  82.3,  78.3,  69.7,  71.6};
}

inline io::InputLocation at(int line) {
  io::InputLocation w;
  w.file = "test.cgl";
  w.line = line;
  return w;
}

inline SurfaceRecord lambert(double kd, double colour, double kr = 0, double kt = 0,
                             double index = 0) {
  SurfaceRecord s;
  s.model = ShadingModel::Lambert;
  s.diffuse = kd;
  s.colour = flat(colour);
  s.reflect = kr;
  s.refract = kt;
  s.index = index;
  s.where = at(100);
  return s;
}

inline SurfaceRecord phong(double kd, double ks, double e, double colour, double kr = 0,
                           double kt = 0, double index = 0) {
  SurfaceRecord s = lambert(kd, colour, kr, kt, index);
  s.model = ShadingModel::Phong;
  s.specular = ks;
  s.exponent = e;
  return s;
}

inline NodeRecord node(int number, NodeKind kind, int down, int right) {
  NodeRecord n;
  n.number = number;
  n.kind = kind;
  n.down = down;
  n.right = right;
  n.where = at(1000 + number);
  return n;
}

inline NodeRecord sphere(int number, int right, int surface, Vec3 centre, double radius) {
  NodeRecord n = node(number, NodeKind::Sphere, 0, right);
  n.surface = surface;
  n.xyz = centre;
  n.radius = radius;
  n.textureAxis1 = 'x';
  n.textureAxis2 = 'y';
  return n;
}

inline NodeRecord polygon(int number, int right, int surface, std::vector<int> vertices) {
  NodeRecord n = node(number, NodeKind::Polygon, 0, right);
  n.surface = surface;
  n.vertices = std::move(vertices);
  return n;
}

inline NodeRecord cylinder(int number, int right, int surface, double radius, int a, int b) {
  NodeRecord n = node(number, NodeKind::Cylinder, 0, right);
  n.surface = surface;
  n.radius = radius;
  n.vertices = {a, b};
  return n;
}

inline NodeRecord transform(int number, NodeKind kind, int down, int right, Vec3 xyz) {
  NodeRecord n = node(number, kind, down, right);
  n.xyz = xyz;
  return n;
}

inline NodeRecord rotate(int number, int down, int right, char axis, double theta) {
  NodeRecord n = node(number, NodeKind::Rotate, down, right);
  n.axis = axis;
  n.theta = theta;
  return n;
}

// The document's defaults (Table 8 and Appendix 1 section 6), no lights, no
// ambience, no nodes; the caller fills in the rest and sets numbers.root.
inline SceneFile emptyScene() {
  SceneFile f;
  f.path = "test.cgl";
  f.ambience.where = at(50);
  return f;
}

inline LightRecord infinityLight(Vec3 direction, double dw, const Spectrum& colour) {
  LightRecord l;
  l.kind = LightKind::Infinity;
  l.xyz = direction;
  l.dw = dw;
  l.colour = colour;
  l.where = at(60);
  return l;
}

// A 2 x 2 square in the y = 0 plane, vertices 1-4 as Figure 59 numbers them.
inline std::vector<Vec3> floorVertices() {
  return {{-1.0, 0.0, -1.0}, {-1.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, {1.0, 0.0, -1.0}};
}

// Figure 59, as scenes/cgl/checkerboard.cgl repairs it: depth 3, shadows,
// xleft 31, xright 480, yhigh 286; the floor rotated x -22 after a translate
// of -0.8 in y; the mirror ball at (0.3, -0.18, 0.0), radius 0.16, on the
// rotate node's right pointer.
inline SceneFile checkerboardScene() {
  SceneFile f = emptyScene();
  f.path = "checkerboard.cgl";
  f.program.depth = 3;
  f.program.shadows = true;
  f.program.xleft = 31;
  f.program.xright = 480;
  f.program.yhigh = 286;
  f.vertices = floorVertices();
  SurfaceRecord floor = lambert(7.0, 0.0);
  floor.textured = true;
  floor.texture = "/u/majsweeney/textures/checkerboard";
  floor.where = at(22);
  f.surfaces.push_back(floor);
  SurfaceRecord ball = phong(0.0, 2.5, 25.0, 0.06, 1.0);
  ball.where = at(25);
  f.surfaces.push_back(ball);
  f.ambience.ka = 0.0005;
  f.ambience.colour = d6500();
  f.lights.push_back(infinityLight({0.6, 1.0, 0.6}, 0.0006, d6500()));
  f.nodes.push_back(rotate(1, 2, 4, 'x', -22.0));
  f.nodes.push_back(transform(2, NodeKind::Translate, 3, 0, {0.0, -0.8, 0.0}));
  f.nodes.push_back(polygon(3, 0, 1, {4, 3, 2, 1}));
  f.nodes.push_back(sphere(4, 0, 2, {0.3, -0.18, 0.0}, 0.16));
  f.numbers.root = 1;
  return f;
}

// A green/blue checkerboard of 8 x 8 squares of 64 texels (the document's
// texture is lost): green where (row / 64 + column / 64) is even.
inline constexpr int kGreen[3] = {30, 160, 40};
inline constexpr int kBlue[3] = {20, 40, 170};
inline Frame checkerboardTexture() {
  Frame f;
  for (int row = 0; row < Frame::kSize; ++row)
    for (int col = 0; col < Frame::kSize; ++col) {
      const int* c = ((row / 64 + col / 64) % 2 == 0) ? kGreen : kBlue;
      f.words[static_cast<std::size_t>(row) * Frame::kSize + col] = packPixel(c[0], c[1], c[2]);
    }
  return f;
}

}  // namespace prime::cgl::test
