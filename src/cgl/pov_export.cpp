#include "src/cgl/pov_export.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace prime::cgl {

namespace {

constexpr double kPi = std::numbers::pi;

std::string rgbText(const Rgb& c) {
  return "rgb " + povVector({c[0], c[1], c[2]});
}

double luminance(const Spectrum& c) {
  return spectrumToXyz(c).y;
}

// The determinant and inverse of the 3 x 3 matrix with rows a, b, c (used
// for the polygon corners and the texture matrices). False when singular.
bool invertRows(const Vec3& a, const Vec3& b, const Vec3& c, std::array<Vec3, 3>& columns) {
  // The inverse of the matrix with rows a, b, c has the columns
  // (b x c, c x a, a x b) / det.
  const double det = dot(a, cross(b, c));
  const double scale = length(a) * length(b) * length(c);
  if (!(std::fabs(det) > 1e-12 * scale)) return false;
  columns = {cross(b, c) * (1.0 / det), cross(c, a) * (1.0 / det), cross(a, b) * (1.0 / det)};
  return true;
}

// x solving rows . x = rhs, from invertRows' columns.
Vec3 solve(const std::array<Vec3, 3>& columns, const Vec3& rhs) {
  return columns[0] * rhs[0] + columns[1] * rhs[1] + columns[2] * rhs[2];
}

// A texture's (u, v) as affine functions of the world point (sections 2.3,
// 3.3, 4.3): u = au.P + bu, v = av.P + bv on the object's surface.
struct UvMap {
  Vec3 au{}, av{};
  double bu = 0, bv = 0;
};

UvMap uvMap(const Object& o) {
  UvMap m;
  switch (o.kind) {
    case ObjectKind::Sphere:
      // u = ((N.A1) + 1)/2 with N = (P - C)/r on the sphere.
      m.au = o.a1 * (0.5 / o.r);
      m.bu = 0.5 - dot(o.c, o.a1) * (0.5 / o.r);
      m.av = o.a2 * (0.5 / o.r);
      m.bv = 0.5 - dot(o.c, o.a2) * (0.5 / o.r);
      break;
    case ObjectKind::Cylinder:
      // u = u_i = (P - A).P/(P.P); v = ((N.A1) + 1)/2 with N = (P - A - u_i
      // P)/r, and A1 is perpendicular to the axis: N.A1 = (P - A).A1/r.
      m.au = o.p * (1.0 / o.pp);
      m.bu = -dot(o.a, o.p) / o.pp;
      m.av = o.a1 * (0.5 / o.r);
      m.bv = 0.5 - dot(o.a, o.a1) * (0.5 / o.r);
      break;
    case ObjectKind::Polygon: {
      // I = V0 + u' E1 + v' N_E1 (E1 and N_E1 are perpendicular), then
      // normalised by the extents over the vertices.
      const double du = (o.umax - o.umin) * dot(o.e1, o.e1);
      const double dv = (o.vmax - o.vmin) * dot(o.ne1, o.ne1);
      m.au = o.e1 * (1.0 / du);
      m.bu = -dot(o.v0, o.e1) / du - o.umin / (o.umax - o.umin);
      m.av = o.ne1 * (1.0 / dv);
      m.bv = -dot(o.v0, o.ne1) / dv - o.vmin / (o.vmax - o.vmin);
      break;
    }
    case ObjectKind::Fractal:
      fractalUvMap(o.v0, o.e1, o.ne1, o.umin, o.umax, o.vmin, o.vmax, m.au, m.bu, m.av, m.bv);
      break;
    case ObjectKind::Box:
    case ObjectKind::Spline:
      break;
  }
  return m;
}

// POV-Ray's planar image_map lays the image on local x, y in [0, 1) (x the
// column from the left, y the row from the bottom; repeated outside). CGL's
// texel is row u_i = int(512 u umod) from the top, column v_i = int(512 v
// vmod) (section 10, CGL-Q50): local x = v vmod, local y = -u umod (its
// fraction 1 - frac(u umod) puts row u_i counted from the top), local z
// along the third axis. The `matrix` takes local to world: the inverse of
// P -> local. "" when the map is degenerate (a sphere with A1 = A2).
std::string textureMatrix(const Object& o, const Surface& s) {
  const UvMap m = uvMap(o);
  const Vec3 rx = m.av * s.vmod, ry = m.au * (-s.umod);
  const double cx = m.bv * s.vmod, cy = -m.bu * s.umod;
  const Vec3 zAxis = cross(rx, ry);
  if (!(length(zAxis) > 0.0)) return "";
  const Vec3 rz = normalized(zAxis);
  std::array<Vec3, 3> inv{};
  if (!invertRows(rx, ry, rz, inv)) return "";
  // local = R P + c  =>  P = R^-1 local - R^-1 c; POV-Ray's matrix rows are
  // the images of local x, y, z (R^-1's columns), then the translation.
  const Vec3 t = -solve(inv, {cx, cy, 0.0});
  return povMatrix(inv[0], inv[1], inv[2], t);
}

Spectrum texelSpectrum(const Texture& tex, std::size_t i) {
  Spectrum d{};
  for (int k = 0; k < 3; ++k) d[Texture::kSamples[k]] = tex.texels[i][static_cast<std::size_t>(k)];
  return d;
}

// Fractions of the 512-pixel frame for POV-Ray's window options.
std::string fraction(int pixels) {
  return povNumber(pixels / 512.0);
}

}  // namespace

PovCamera povCamera(const Camera& camera, bool pixelCorners) {
  // CGL (section 8.2): D = S + (x - 256) X + (y - 256) Y for the screen point
  // (x, y), y up. POV-Ray: direction + ((i + 0.5)/512 - 0.5) right + (0.5 -
  // (r + 0.5)/512) up for column i, row r from the top; with right = 512 X,
  // up = 512 Y and r = 511 - y that is S + (i - 255.5) X + (y - 255.5) Y: the
  // centre (x + 1/2, y + 1/2) of the pixel square.
  PovCamera c;
  c.location = camera.eye;
  c.right = camera.xpath * 512.0;
  c.up = camera.ypath * 512.0;
  c.direction = camera.start;
  if (pixelCorners) c.direction = camera.start - camera.xpath * 0.5 - camera.ypath * 0.5;
  return c;
}

Rgb povRgb(const Spectrum& c, Phosphors phosphors) {
  const auto m = xyzToMonitor(spectrumToXyz(c), phosphors);
  return {m[0] / 255.0, m[1] / 255.0, m[2] / 255.0};
}

Rgb pigmentUnder(const Spectrum& reflectance, const Spectrum& light, Phosphors phosphors) {
  Spectrum lit{};
  for (int k = 0; k < kSpectrumSamples; ++k) lit[k] = reflectance[k] * light[k];
  const Rgb num = povRgb(lit, phosphors), den = povRgb(light, phosphors);
  Rgb p{};
  for (int k = 0; k < 3; ++k) p[k] = den[k] > 0.0 ? num[k] / den[k] : 0.0;
  return p;
}

std::array<Vec3, 4> polygonCorners(const Object& o) {
  std::array<Vec3, 4> v{};
  const int n = o.edges;
  // Corner k lies on edge k (N_Ek . I = d_k, through V_k) and on edge k - 1
  // (through V_k as its far end), in the plane N . I = N . V0.
  const double plane = dot(o.n, o.v0);
  for (int k = 0; k < n; ++k) {
    const int prev = (k + n - 1) % n;
    std::array<Vec3, 3> inv{};
    if (invertRows(o.n, o.en[k], o.en[prev], inv)) v[k] = solve(inv, {plane, o.d[k], o.d[prev]});
  }
  // V0 and V1 are exact in the object (V0, V0 + E1): keep their bits.
  v[0] = o.v0;
  if (n > 1) v[1] = o.v0 + o.e1;
  return v;
}

// A B-spline surface (section 6) as POV-Ray 3.7 bicubic patches, each
// uniform B-spline patch converted exactly to Bezier form (bezierPatches).
// The texture of a spline is not mapped (its mean colour is used).
std::string povSpline(const SplineSurface& sp) {
  std::string s = "union {";
  for (const auto& patch : bezierPatches(sp)) {
    s += "\n  bicubic_patch { type 1 flatness 0.001 u_steps 4 v_steps 4";
    for (int k = 0; k < 16; ++k) s += (k % 4 == 0 ? "\n   " : ",") + povVector(patch[k]);
    s += " }";
  }
  return s + "\n}";
}

std::string povGeometry(const Object& o) {
  switch (o.kind) {
    case ObjectKind::Sphere:
      return "sphere { " + povVector(o.c) + ", " + povNumber(o.r) + " }";
    case ObjectKind::Cylinder:
      // Section 3: no end caps.
      return "cylinder { " + povVector(o.a) + ", " + povVector(o.a + o.p) + ", " + povNumber(o.r) +
             " open }";
    case ObjectKind::Polygon: {
      const auto v = polygonCorners(o);
      if (o.edges == 3)
        return "triangle { " + povVector(v[0]) + ", " + povVector(v[1]) + ", " + povVector(v[2]) +
               " }";
      // A closed polygon: the first corner repeated.
      std::string s = "polygon { " + std::to_string(o.edges + 1);
      for (int k = 0; k <= o.edges; ++k) s += ", " + povVector(v[k % o.edges]);
      return s + " }";
    }
    case ObjectKind::Fractal:  // needs the scene's tree: povFractalMesh (src/cgl/fractal.h)
    case ObjectKind::Box:
    case ObjectKind::Spline:
      break;
  }
  return "";
}

namespace {

// The scene's export, one section at a time (the POV-Ray file's order).
class CglPovWriter {
 public:
  CglPovWriter(const Scene& scene, const PovExportOptions& options)
      : scene_(scene), options_(options), prog_(options.program), ph_(options.phosphors) {}

  PovExport run() {
    mainLight();
    commandLine();
    header();
    lights();
    images();
    for (const Object& o : scene_.objects) object(o);
    if (out_.boxesOmitted > 0)
      out_.pov += "// " + std::to_string(out_.boxesOmitted) +
                  " super box(es) not written: POV-Ray bounds the objects itself.\n";
    return std::move(out_);
  }

 private:
  void mainLight() {
    // The main light: the brightest (luminance of I dw); colours are taken
    // under its spectrum. Without lights, the ambience's; without either, a
    // flat spectrum.
    reference_.fill(1.0);
    double best = -1.0;
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
      const double y = luminance(scene_.lights[i].intensityDw);
      if (y > best) {
        best = y;
        out_.mainLight = static_cast<int>(i);
      }
    }
    if (out_.mainLight >= 0)
      reference_ = scene_.lights[static_cast<std::size_t>(out_.mainLight)].intensity;
    else if (luminance(scene_.ambient) > 0.0)
      reference_ = scene_.ambient;
  }

  void commandLine() {
    // Command-line options: the window as fractions of 512 (POV-Ray rows from
    // the top: scanline yhigh is row 511 - yhigh), and the anti-aliasing.
    std::string& args = out_.povArgs;
    args = "+W512 +H512";
    if (prog_.xleft != 0 || prog_.xright != 511)
      args += " +SC" + fraction(prog_.xleft) + " +EC" + fraction(prog_.xright + 1);
    if (prog_.ylow != 0 || prog_.yhigh != 511)
      args += " +SR" + fraction(511 - prog_.yhigh) + " +ER" + fraction(512 - prog_.ylow);
    if (prog_.aalevel == 0) {
      args += " -A";
    } else {
      // Subdivid at level L samples an (L + 1) x (L + 1) grid of points over a
      // pixel that differs: POV-Ray's method 1 with +R(L + 1) samples as many;
      // aathreshold is a sum of |dr| + |dg| + |db| in 0..255, POV-Ray's +A a
      // sum over 0..1.
      char buf[96];
      std::snprintf(buf, sizeof buf, " +A%.4f +AM1 +R%d", prog_.aathreshold / 255.0,
                    prog_.aalevel + 1);
      args += buf;
    }
  }

  void header() {
    const std::string& args = out_.povArgs;
    std::string& s = out_.pov;
    s += "// " + scene_.path +
         ": a Waterloo CGL (1985) scene exported by `prime export-pov`.\n"
         "// Render: povray +I<this file> " +
         args + " File_Gamma=1.0\n";
    s += "// Colours are the RGB of each spectrum under the main light (";
    s += out_.mainLight >= 0
             ? "light " + std::to_string(out_.mainLight + 1)
             : std::string(luminance(scene_.ambient) > 0.0 ? "no light: the ambience"
                                                           : "none: a flat spectrum");
    s += "): pigment =\n// L(D * I)/L(I) per channel, light = L(I dw)/255, L = (1/15) M^-1 XYZ.\n";
    s += "#version 3.7;\n\n";
    const Rgb ambient = povRgb(scene_.ambient, ph_);
    s += "global_settings {\n  assumed_gamma 1.0\n  ambient_light " + rgbText(ambient) +
         "  // k_a pi I_a\n  max_trace_level " + std::to_string(prog_.depth + 1) + "  // depth " +
         std::to_string(prog_.depth) +
         " + the primary ray\n  adc_bailout 0  // no weight cut-off (section 8)\n}\n";
    s += "background { " +
         rgbText({prog_.background[0] / 255.0, prog_.background[1] / 255.0,
                  prog_.background[2] / 255.0}) +
         " }\n\n";

    const bool corners = prog_.aalevel == 0;
    const PovCamera cam = povCamera(scene_.camera, corners);
    s += corners ? "// aalevel 0: one ray through each pixel's corner (x, y); POV-Ray shoots the\n"
                   "// pixel's centre, so the direction is moved back half a pixel.\n"
                 : "// Anti-aliased: POV-Ray's pixel centre is the centre of the square whose\n"
                   "// corners CGL's Subdivid samples.\n";
    s += "camera {\n  perspective\n  location " + povVector(cam.location) + "\n  direction " +
         povVector(cam.direction) + "\n  right " + povVector(cam.right) + "\n  up " +
         povVector(cam.up) + "\n}\n\n";
  }

  void lights() {
    std::string& s = out_.pov;
    // Lights (section 9.3): no fall-off with distance in either kind.
    const std::string shadowless = prog_.shadows ? "" : " shadowless";
    for (const Light& l : scene_.lights) {
      const Rgb c = povRgb(l.intensityDw, ph_);
      if (l.inScene) {
        s += "light_source { " + povVector(l.xyz) + " " + rgbText(c) + shadowless + " }\n";
      } else {
        // A parallel light from far along the direction to the light; its
        // shadow rays reach the plane through `location`, CGL's reach 10^10.
        s += "light_source { " + povVector(l.xyz * 1e7) + " " + rgbText(c) +
             " parallel point_at <0, 0, 0>" + shadowless + " }\n";
      }
      ++out_.lights;
    }
    s += "\n";
  }

  void images() {
    // Texture images: each texel's reflectance under the main light.
    imageOf_.assign(scene_.textures.size(), -1);
    for (std::size_t t = 0; t < scene_.textures.size(); ++t) {
      bool used = false;
      for (const Surface& sf : scene_.surfaces) used = used || sf.texture == static_cast<int>(t);
      if (!used) continue;
      const Texture& tex = scene_.textures[t];
      std::vector<Rgb> pig(tex.texels.size());
      double top = 1.0;
      for (std::size_t i = 0; i < tex.texels.size(); ++i) {
        pig[i] = pigmentUnder(texelSpectrum(tex, i), reference_, ph_);
        for (double c : pig[i]) top = std::max(top, c);
      }
      PovImage img;
      img.file =
          options_.textureStem + "-texture" + std::to_string(out_.images.size() + 1) + ".png";
      img.scale = top;
      for (std::size_t i = 0; i < pig.size() && i < img.frame.words.size(); ++i) {
        int ch[3];
        for (int k = 0; k < 3; ++k)
          ch[k] = static_cast<int>(std::lround(std::clamp(pig[i][k] / top, 0.0, 1.0) * 255.0));
        img.frame.words[i] = packPixel(ch[0], ch[1], ch[2]);
      }
      imageOf_[t] = static_cast<int>(out_.images.size());
      out_.images.push_back(std::move(img));
    }
  }

  void object(const Object& o) {
    if (o.kind == ObjectKind::Box) {
      ++out_.boxesOmitted;
      return;
    }
    const Surface& sf = scene_.surfaces[static_cast<std::size_t>(o.surface)];
    const std::string geometry =
        o.kind == ObjectKind::Fractal
            ? povFractalMesh(scene_.fractals[static_cast<std::size_t>(o.fractal)])
        : o.kind == ObjectKind::Spline
            ? povSpline(scene_.splines[static_cast<std::size_t>(o.spline)])
            : povGeometry(o);
    // CGL adds k_t T to the whole colour; POV-Ray's transmit t scales the
    // diffuse and ambient terms by 1 - t, which the finish divides out (for
    // k_t < 1; k_t >= 1 keeps POV-Ray's none). The reflected and transmitted
    // shares are added unfiltered in both; the ior is CGL's index entering and
    // 1/index leaving (CGL-Q45), as POV-Ray's interior does.
    const bool transparent = sf.kt > 0.0;
    const double undo = transparent && sf.kt < 1.0 ? 1.0 / (1.0 - sf.kt) : 1.0;
    double scale = 1.0;
    std::string pigment;
    std::string matrix;
    if (sf.texture >= 0 && imageOf_[static_cast<std::size_t>(sf.texture)] >= 0 &&
        o.kind != ObjectKind::Spline)
      matrix = textureMatrix(o, sf);
    const std::string transmit = transparent ? " transmit " + povNumber(sf.kt) : "";
    if (!matrix.empty()) {
      const PovImage& img = out_.images[static_cast<std::size_t>(imageOf_[sf.texture])];
      scale = img.scale;
      // gamma 1.0: the bytes are linear (POV-Ray 3.7 would decode a PNG as
      // sRGB under assumed_gamma 1.0).
      pigment = "pigment { image_map { png \"" + img.file + "\" gamma 1.0" +
                (transparent ? " transmit all " + povNumber(sf.kt) : std::string()) + " } " +
                matrix + " }";
    } else {
      Spectrum d = sf.colour;
      if (sf.texture >= 0) {
        // A degenerate map (A1 = A2): the texture's mean colour.
        const Texture& tex = scene_.textures[static_cast<std::size_t>(sf.texture)];
        d.fill(0.0);
        for (std::size_t i = 0; i < tex.texels.size(); ++i) {
          const Spectrum t = texelSpectrum(tex, i);
          for (int k = 0; k < kSpectrumSamples; ++k)
            d[k] += t[k] / static_cast<double>(tex.texels.size());
        }
      }
      pigment = "pigment { " + rgbText(pigmentUnder(d, reference_, ph_)) + transmit + " }";
    }
    std::string finish = "finish { ambient " + povNumber(options_.ambientFactor * scale * undo) +
                         " diffuse " + povNumber(sf.kd * scale * undo);
    if (sf.model == ShadingModel::Phong && sf.ks > 0.0)
      finish += " phong " + povNumber(sf.ks) + " phong_size " + povNumber(sf.e);
    if (sf.model == ShadingModel::Cook && sf.m > 0.0 && !sf.fresnel.empty()) {
      // CGL-D101: Cook-Torrance approximated. The highlight: POV-Ray's
      // specular (N.H)^(1/roughness), tinted by the pigment (metallic), with
      // k_s/m^2 and roughness m^2/(2 - 4m^2), which match the Beckmann D's
      // peak k_s F_0/(pi m^2) (for D = F_0/pi, as prime cook writes) and its
      // curvature at N.H = 1; the reflection: CGL's weight for the mirror
      // direction at normal incidence, k_r (k_s F_0/(pi m^2) + k_d D), as an
      // RGB filter. Not expressed: G, the 1/(N.V) growth and the Fresnel
      // table's change with the angle.
      const double m2 = sf.m * sf.m;
      finish += " specular " + povNumber(sf.ks / m2) + " roughness " +
                povNumber(m2 / std::max(2.0 - 4.0 * m2, 1e-3)) + " metallic";
      if (sf.kr > 0.0) {
        Spectrum w{};
        for (int k = 0; k < kSpectrumSamples; ++k)
          w[k] = sf.kr * (sf.ks * sf.fresnel[0][k] / (kPi * m2) + sf.kd * sf.colour[k]);
        finish += " reflection { " + rgbText(pigmentUnder(w, reference_, ph_)) + " }";
      }
    } else if (sf.kr > 0.0) {
      finish += " reflection { " + povNumber(sf.kr) + " }";
    }
    finish += " }";
    std::string material = "texture { " + pigment + " " + finish + " }";
    if (transparent) material += " interior { ior " + povNumber(sf.index) + " }";
    // Section 9.3: objects that are not opaque are ignored by shadow rays.
    if (!o.opaque) material += " no_shadow";
    out_.pov +=
        "// node " + std::to_string(o.node) + ", surface " + std::to_string(sf.number) + "\n";
    out_.pov += geometry.substr(0, geometry.size() - 1) + material + " }\n";
    ++out_.objects;
  }

  const Scene& scene_;
  const PovExportOptions& options_;
  const ProgramParameters& prog_;
  const Phosphors ph_;
  PovExport out_;
  Spectrum reference_{};      // the main light's spectrum: colours are taken under it
  std::vector<int> imageOf_;  // texture -> its image in out_.images, or -1 (unused)
};

}  // namespace

PovExport exportPov(const Scene& scene, const PovExportOptions& options) {
  return CglPovWriter(scene, options).run();
}

}  // namespace prime::cgl
