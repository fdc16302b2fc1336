#include "src/malone/pov_export.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "legacy_io/common/output_file.h"

namespace prime::malone {

namespace {

std::string rgbText(const Rgb& c) {
  return "rgb " + povVector({c[0], c[1], c[2]});
}

// Rows of POV-Ray's `matrix`: the images of the local x, y and z axes, then
// the translation (p_world = p_local * M with row vectors).
std::string matrixText(const Vec3& x, const Vec3& y, const Vec3& z, const Vec3& o) {
  return povMatrix(x, y, z, o);
}

// A finite open cone piece from parameter u0 to u1 along the axis (both on
// one nappe: u0 * u1 >= 0), radius |u| |a| tan(theta).
std::string conePiece(const Primitive& p, double u0, double u1, double tanTheta) {
  const double len = std::sqrt(p.axis2);
  return "cone { " + povVector(p.c + p.axis * u0) + ", " +
         povNumber(std::fabs(u0) * len * tanTheta) + ", " + povVector(p.c + p.axis * u1) + ", " +
         povNumber(std::fabs(u1) * len * tanTheta) + " open }";
}

std::string triangleText(const Primitive& p) {
  return "triangle { " + povVector(p.c) + ", " + povVector(p.c + p.a) + ", " +
         povVector(p.c + p.b) + " }";
}

}  // namespace

PovCamera povCamera(const Viewer& v) {
  // Malone's ray for pixel (X, Y) points along
  //   w + alpha x + beta y,  w = (l - e)/|l - e|,
  //   alpha = (2X - W)/W,  beta = -(2Y - H)/H          (no half-pixel offset),
  // while POV-Ray's perspective camera samples pixel centres:
  //   direction + ((X + 0.5)/W - 0.5) right + (0.5 - (Y + 0.5)/H) up.
  // With right = 2x and up = 2y that is w + (alpha + 1/W) x + (beta - 1/H) y:
  // half a pixel right and down. Moving `direction` back by that half pixel,
  // direction = w - x/W + y/H, gives Malone's ray exactly (up to rounding).
  // POV-Ray takes explicit vectors as they are: no orthonormalisation, no
  // aspect correction, as Malone's x and y are used (MAL-Q23).
  PovCamera c;
  const Vec3 toLook = v.lookAt - v.eye;
  const Vec3 w = toLook * (1.0 / length(toLook));
  c.location = v.eye;
  c.right = v.x * 2.0;
  c.up = v.y * 2.0;
  c.direction = w - v.x * (1.0 / v.xRes) + v.y * (1.0 / v.yRes);
  return c;
}

std::string povGeometry(const Scene& scene, const Primitive& p) {
  switch (p.id) {
    case ObjectId::Sphere:
      return "sphere { " + povVector(p.c) + ", " + povNumber(p.r) + " }";
    case ObjectId::Plane:
      // n.x = D with a unit n: POV-Ray's plane { n, D } is the same set.
      return "plane { " + povVector(p.n) + ", " + povNumber(p.D) + " }";
    case ObjectId::Disk:
      return "disc { " + povVector(p.c) + ", " + povVector(p.n) + ", " + povNumber(p.r) + " }";
    case ObjectId::Annulus:
      return "disc { " + povVector(p.c) + ", " + povVector(p.n) + ", " + povNumber(p.r) + ", " +
             povNumber(std::sqrt(p.rIn2)) + " }";
    case ObjectId::Triangle:
      return triangleText(p);
    case ObjectId::Parallelogram:
      // v, v + a, v + a + b, v + b, closed by repeating v.
      return "polygon { 5, " + povVector(p.c) + ", " + povVector(p.c + p.a) + ", " +
             povVector(p.c + p.a + p.b) + ", " + povVector(p.c + p.b) + ", " + povVector(p.c) +
             " }";
    case ObjectId::Polygon: {
      // POV-Ray's polygon is even-odd, as Malone's inside test (MAL-Q15).
      std::string s = "polygon { " + std::to_string(p.count + 1);
      for (int i = 0; i <= p.count; ++i)
        s += ", " +
             povVector(scene.polygonVertices[static_cast<std::size_t>(p.first + i % p.count)]);
      return s + " }";
    }
    case ObjectId::Cone: {
      // The double cone about the axis through the apex c with half-angle
      // acos(alpha), cut to lo <= (x - c).a/|a|^2 <= hi (MAL-Q14): one open
      // cone per nappe the range covers, each from (or towards) the apex.
      const double tanTheta = std::sqrt(1.0 - p.alpha2) / p.alpha;
      if (!(p.hi > p.lo))
        return "// cone: an empty range (" + povNumber(p.lo) + " to " + povNumber(p.hi) +
               "), nothing to draw";
      if (p.lo >= 0 || p.hi <= 0) return conePiece(p, p.lo, p.hi, tanTheta);
      return "union { " + conePiece(p, p.lo, 0, tanTheta) + " " + conePiece(p, 0, p.hi, tanTheta) +
             " }";
    }
    case ObjectId::Cylinder:
      if (!(p.hi > p.lo))
        return "// cylinder: an empty range (" + povNumber(p.lo) + " to " + povNumber(p.hi) +
               "), nothing to draw";
      return "cylinder { " + povVector(p.c + p.axis * p.lo) + ", " +
             povVector(p.c + p.axis * p.hi) + ", " + povNumber(p.r) + " open }";
    case ObjectId::Torus: {
      // POV-Ray's torus lies about its y axis: the matrix takes y onto the
      // unit axis u, x and z onto two unit vectors perpendicular to it
      // (e2 = e1 x u, so the rotation has determinant +1), then to c.
      const Vec3& u = p.u;
      const Vec3 helper =
          std::fabs(u[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};  // not parallel to u
      Vec3 e1 = cross(helper, u);
      e1 = e1 * (1.0 / length(e1));
      const Vec3 e2 = cross(e1, u);
      return "torus { " + povNumber(p.R) + ", " + povNumber(p.r) + " " +
             matrixText(e1, u, e2, p.c) + " }";
    }
    case ObjectId::Affine: {
      // world = O + (X Y Z) local: rows X, Y, Z, O of POV-Ray's matrix.
      const Affine& a = scene.affines[static_cast<std::size_t>(p.affine)];
      const Primitive& inner = scene.embedded[static_cast<std::size_t>(a.inner)];
      const Vec3 X{a.mInv[0][0], a.mInv[1][0], a.mInv[2][0]};
      const Vec3 Y{a.mInv[0][1], a.mInv[1][1], a.mInv[2][1]};
      const Vec3 Z{a.mInv[0][2], a.mInv[1][2], a.mInv[2][2]};
      return "object { " + povGeometry(scene, inner) + " " + matrixText(X, Y, Z, p.c) + " }";
    }
    default:
      break;
  }
  return "// unknown primitive";
}

std::string povMaterial(const Surface& s) {
  // Malone per light: I (k_d colour (d.s) + k_s (r.s)^k_e) [/ l^2]; ambient
  // A k_d colour; k_s' trace(reflected) + k_t trace(transmitted).
  // POV-Ray: pigment diffuse (N.L) + phong (R.L)^phong_size, both times the
  // light; pigment ambient ambient_light; reflection and transmit add the
  // rays' colours unfiltered. POV-Ray scales the diffuse and ambient terms of
  // a surface with transmit t by 1 - t, so the pigment is divided by 1 - k_t.
  Rgb pigment = s.colour;
  const bool transparent = s.kt > 0;
  std::string transmit;
  if (transparent) {
    if (s.kt < 1)
      for (double& c : pigment) c /= 1.0 - s.kt;
    transmit = " transmit " + povNumber(s.kt);
  }
  std::string t = "texture { pigment { " + rgbText(pigment) + transmit + " } finish { ambient " +
                  povNumber(s.diffuse) + " diffuse " + povNumber(s.diffuse);
  if (s.ks > 0)
    t += " phong " + povNumber(s.ks) + " phong_size " + povNumber(s.ke) + " reflection { " +
         povNumber(s.ks) + " }";
  t += " } }";
  if (transparent) t += " interior { ior " + povNumber(s.index) + " }";
  return t;
}

PovExport exportPov(const Scene& scene, const PovExportOptions& options) {
  PovExport out;
  const Viewer& v = scene.viewer;
  out.width = v.xRes;
  out.height = v.yRes;
  std::string& s = out.pov;
  s += "// " + scene.name + ": a Malone (1995) scene exported by `prime export-pov`.\n";
  s += "// Render: povray +I<this file> +W" + std::to_string(v.xRes) + " +H" +
       std::to_string(v.yRes) + " -A File_Gamma=1.0\n";
  s += "#version 3.7;\n\n";
  Rgb ambient = scene.hasAmbient ? scene.ambient : Rgb{0, 0, 0};
  s += "global_settings {\n  assumed_gamma 1.0\n  ambient_light " + rgbText(ambient) +
       "\n  max_trace_level " + std::to_string(options.maxDepth) + "  // --max-depth\n" +
       "  adc_bailout " + povNumber(options.minWeight) + "  // MIN_WEIGHT\n}\n";
  s += "background { rgb 0 }  // an escaped ray is black (MAL-Q6)\n\n";

  const PovCamera cam = povCamera(v);
  s += "// POV-Ray samples pixel centres, Malone the pixel corner (no half-pixel\n"
       "// offset): direction = w - x/X_RES + y/Y_RES undoes the half-pixel shift.\n";
  s += "camera {\n  perspective\n  location " + povVector(cam.location) + "\n  direction " +
       povVector(cam.direction) + "\n  right " + povVector(cam.right) + "\n  up " +
       povVector(cam.up) + "\n}\n\n";

  // 101: Malone divides by l^2. POV-Ray's fade_power 2 multiplies the colour
  // by 2 / (1 + (d/f)^2); with the colour C / (2 f^2) that is
  // C / (d^2 + f^2): Malone's C / d^2 within a factor 1 - f^2/d^2.
  // 104: no fade. 105: its samples (Malone's deterministic lattice), each a
  // 101 light of 1/samples of the spectrum.
  const double f = options.fadeDistance;
  for (const LightSample& l : scene.lights) {
    if (l.inverseSquare) {
      const double scale = 1.0 / (2.0 * f * f);
      s += "light_source { " + povVector(l.position) + " " +
           rgbText({l.rgb[0] * scale, l.rgb[1] * scale, l.rgb[2] * scale}) + " fade_distance " +
           povNumber(f) + " fade_power 2 }\n";
    } else {
      s += "light_source { " + povVector(l.position) + " " + rgbText(l.rgb) + " }\n";
    }
    ++out.lights;
  }
  s += "\n";

  std::vector<std::string> materials;
  materials.reserve(scene.surfaces.size());
  for (const Surface& surface : scene.surfaces) materials.push_back(povMaterial(surface));

  const auto& prims = scene.primitives;
  for (std::size_t i = 0; i < prims.size();) {
    const Primitive& p = prims[i];
    const std::string& material = materials[static_cast<std::size_t>(p.surface)];
    // A run of triangles with one surface: one mesh.
    std::size_t j = i + 1;
    if (p.id == ObjectId::Triangle)
      while (j < prims.size() && prims[j].id == ObjectId::Triangle && prims[j].surface == p.surface)
        ++j;
    if (j - i >= 2) {
      s += "mesh {\n";
      for (std::size_t k = i; k < j; ++k) s += "  " + triangleText(prims[k]) + "\n";
      s += "  " + material + "\n}\n";
    } else {
      const std::string g = povGeometry(scene, p);
      if (g.rfind("//", 0) == 0) {
        s += g + "\n";
        i = j;
        continue;
      }
      // Insert the material before the object's closing brace.
      s += g.substr(0, g.size() - 1) + material + " }\n";
    }
    ++out.objects;
    i = j;
  }
  return out;
}

void writePovFile(const std::string& text, const std::filesystem::path& file) {
  io::OutputFile out(file.string());
  out.write(text);
  out.commit();
}

}  // namespace prime::malone
