// prime probe SCENE.cgl --pixel X Y (or --point X Y, the package's own
// screen point): one primary ray through a pixel's integer corner, as the
// build without anti-aliasing traced it (--point's fractions reach the
// sub-pixel corners of Figure 44), and everything it did: every ray it spawned, what each hit, the
// texture indices, each light's terms (Cook-Torrance: D, G, the
// Fresnel row and S, and the reflected and transmitted rays as lights) and why a light was skipped,
// the colour-vector, XYZ and the RGB ToRGB made of it.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "src/cli/cgl/commands.h"
#include "src/cli/cgl/options.h"
#include "src/cli/cgl/probe_pixel.h"
#include "src/cli/overlay.h"
#include "src/cli/system.h"
#include "src/render/probe_log.h"

namespace prime::cli::cgl {

namespace {

const char* rayName(RayKind k) {
  switch (k) {
    case RayKind::Primary:
      return "primary";
    case RayKind::Reflected:
      return "reflected";
    case RayKind::Transmitted:
      return "refracted";
    case RayKind::Shadow:
      return "shadow";
  }
  return "?";
}

void printSpectrum(std::FILE* out, const char* indent, const prime::cgl::Spectrum& c) {
  for (int i = 0; i < prime::cgl::kSpectrumSamples; ++i) {
    if (i % 11 == 0) std::fprintf(out, "%s%3d nm:", indent, 380 + 10 * i);
    std::fprintf(out, " %.5g", c[static_cast<std::size_t>(i)]);
    if (i % 11 == 10 || i + 1 == prime::cgl::kSpectrumSamples) std::fprintf(out, "\n");
  }
}

void printReport(std::FILE* out, const prime::cgl::ProbeReport& r, const prime::cgl::Scene& scene) {
  std::fprintf(out, "screen point (%g, %g)\n", r.x, r.y);
  for (const auto& ray : r.rays) {
    std::string indent(static_cast<std::size_t>(2 * ray.level + 2), ' ');
    std::fprintf(out,
                 "%s%s ray, level %d: origin (%.6g, %.6g, %.6g) direction (%.6g, %.6g, %.6g)\n",
                 indent.c_str(), rayName(ray.kind), ray.level, ray.origin[0], ray.origin[1],
                 ray.origin[2], ray.direction[0], ray.direction[1], ray.direction[2]);
    if (!ray.hit) {
      std::fprintf(out, "%s  hits nothing: the background\n", indent.c_str());
      continue;
    }
    std::fprintf(
        out,
        "%s  hits object %d (%s, scene node %d, surface %d) at t = %.9g, point (%.6g, %.6g, "
        "%.6g), normal facing the viewer (%.6g, %.6g, %.6g)\n",
        indent.c_str(), ray.object, prime::cgl::kindName(ray.objectKind), ray.node, ray.surface,
        ray.t, ray.point[0], ray.point[1], ray.point[2], ray.normal[0], ray.normal[1],
        ray.normal[2]);
    if (ray.facet >= 0)
      std::fprintf(out, "%s  the fractal's facet %d (leaf order, section 5.6)\n", indent.c_str(),
                   ray.facet);
    if (ray.objectKind == prime::cgl::ObjectKind::Spline)
      std::fprintf(out,
                   "%s  spline (u-bar, v-bar) = (%.9g, %.9g): Newton from the leaf's start (%.6g, "
                   "%.6g), %d iteration(s)\n",
                   indent.c_str(), ray.splineU, ray.splineV, ray.newtonU0, ray.newtonV0,
                   ray.newtonIterations);
    if (ray.textured)
      std::fprintf(out, "%s  texture u %.6f v %.6f: texel row %d, column %d\n", indent.c_str(),
                   ray.u, ray.v, ray.ui, ray.vi);
    if (ray.atDepthLimit)
      std::fprintf(out,
                   "%s  at the depth limit: reflected and refracted colours are the background\n",
                   indent.c_str());
    for (const auto& l : ray.lights) {
      if (l.light == prime::cgl::ProbeLight::kReflectedLight)
        std::fprintf(out, "%s  reflected ray as a light (R, dw = k_r %.6g)", indent.c_str(), l.dw);
      else if (l.light == prime::cgl::ProbeLight::kTransmittedLight)
        std::fprintf(out, "%s  transmitted ray as a light (T, dw = k_t %.6g)", indent.c_str(),
                     l.dw);
      else
        std::fprintf(out, "%s  light %d", indent.c_str(), l.light + 1);
      std::fprintf(out, ": L (%.6g, %.6g, %.6g), N.L %.6g", l.l[0], l.l[1], l.l[2], l.nl);
      if (!l.skipped.empty()) {
        std::fprintf(out, ", skipped: %s", l.skipped.c_str());
        if (l.shadowedBy >= 0)
          std::fprintf(out, " by object %d (scene node %d)", l.shadowedBy,
                       scene.objects[static_cast<std::size_t>(l.shadowedBy)].node);
        std::fprintf(out, "\n");
      } else if (l.cook) {
        std::fprintf(
            out,
            ", Cook-Torrance: D %.6g, G %.6g, Fresnel row %d, S/F = DG/(pi(N.L)(N.V)) %.6g, "
            "diffuse k_d(N.L) %.6g, specular k_s(N.L)S/F %.6g\n",
            l.d, l.g, l.fresnel, l.s, l.diffuse, l.specular);
      } else {
        std::fprintf(out, ", diffuse k_d(N.L) %.6g, specular k_s(P.V)^e %.6g\n", l.diffuse,
                     l.specular);
      }
    }
    std::fprintf(out, "%s  colour-vector returned:\n", indent.c_str());
    printSpectrum(out, (indent + "    ").c_str(), ray.colour);
  }
  std::fprintf(out, "colour-vector: \n");
  printSpectrum(out, "  ", r.colour);
  std::fprintf(out, "XYZ (1360 sum c x-bar ...): %.6g %.6g %.6g\n", r.xyz.x, r.xyz.y, r.xyz.z);
  std::fprintf(out, "RGB (ToRGB: (1/15) M^-1 XYZ, clipped, truncated): %d %d %d%s\n", r.rgb.r,
               r.rgb.g, r.rgb.b,
               r.background ? " (the background: the primary ray hit nothing)" : "");
}

std::string text(const prime::cgl::ProbeReport& r, const prime::cgl::Scene& scene) {
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* out = open_memstream(&buffer, &size);
  if (out == nullptr) throw std::runtime_error("probe: no memory for the report");
  printReport(out, r, scene);
  std::fclose(out);
  std::string t(buffer, size);
  std::free(buffer);
  return t;
}

std::string spectrumJson(const prime::cgl::Spectrum& c) {
  std::string s = "[";
  for (std::size_t i = 0; i < c.size(); ++i) s += (i ? "," : "") + json(c[i]);
  return s + "]";
}

// The events of the shared probe schema, from the report's rays.
std::string eventsJson(const prime::cgl::ProbeReport& r) {
  ProbeLog log;
  for (const auto& ray : r.rays) {
    const int d = ray.level;
    log.add(d, "ray", "",
            JsonObject()
                .add("kind", rayName(ray.kind))
                .add("origin", ray.origin)
                .add("direction", ray.direction));
    if (!ray.hit) {
      log.add(d, "miss", "", JsonObject());
      continue;
    }
    JsonObject hit;
    hit.add("object", ray.object)
        .add("kind", prime::cgl::kindName(ray.objectKind))
        .add("node", ray.node)
        .add("surface", ray.surface)
        .add("t", ray.t)
        .add("point", ray.point)
        .add("normal", ray.normal);
    if (ray.facet >= 0) hit.add("facet", ray.facet);
    if (ray.objectKind == prime::cgl::ObjectKind::Spline)
      hit.add("splineU", ray.splineU)
          .add("splineV", ray.splineV)
          .add("newtonIterations", ray.newtonIterations);
    if (ray.atDepthLimit) hit.add("atDepthLimit", true);
    log.add(d, "hit", "", hit);
    if (ray.textured)
      log.add(
          d, "texture", "",
          JsonObject().add("u", ray.u).add("v", ray.v).add("row", ray.ui).add("column", ray.vi));
    for (const auto& l : ray.lights) {
      JsonObject light;
      if (l.light == prime::cgl::ProbeLight::kReflectedLight)
        light.add("light", "reflected");
      else if (l.light == prime::cgl::ProbeLight::kTransmittedLight)
        light.add("light", "transmitted");
      else
        light.add("light", l.light + 1);
      light.add("l", l.l).add("nl", l.nl);
      if (!l.skipped.empty()) {
        light.add("skipped", l.skipped);
        if (l.shadowedBy >= 0) light.add("shadowedBy", l.shadowedBy);
      } else if (l.cook) {
        light.add("cookTorrance", true)
            .add("D", l.d)
            .add("G", l.g)
            .add("fresnelRow", l.fresnel)
            .add("S", l.s)
            .add("dw", l.dw)
            .add("diffuse", l.diffuse)
            .add("specular", l.specular);
      } else {
        light.add("diffuse", l.diffuse).add("specular", l.specular);
      }
      log.add(d, "light", "", light);
    }
    log.add(d, "shade", "", JsonObject().addJson("spectrum", spectrumJson(ray.colour)));
  }
  return log.jsonEvents();
}

}  // namespace

ProbedPixel probePoint(const prime::cgl::Scene& scene, const prime::cgl::RenderSettings& settings,
                       const std::string& file, const std::string& where, double x, double y) {
  const prime::cgl::ProbeReport report = prime::cgl::probe(scene, settings, x, y);
  ProbedPixel out;
  out.text = text(report, scene);
  const Vec3 rgb{report.rgb.r / 255.0, report.rgb.g / 255.0, report.rgb.b / 255.0};
  out.json =
      JsonObject()
          .add("scene", file)
          .add("where", where)
          .addJson("events", eventsJson(report))
          .add("color", rgb)
          .add("rays", static_cast<std::uint64_t>(report.rays.size()))
          .addJson("cgl",
                   JsonObject()
                       .add("system", "Waterloo CGL (1985)")
                       .addJson("screenPoint", "[" + json(report.x) + "," + json(report.y) + "]")
                       .addJson("spectrum", spectrumJson(report.colour))
                       .addJson("xyz", "[" + json(report.xyz.x) + "," + json(report.xyz.y) + "," +
                                           json(report.xyz.z) + "]")
                       .addJson("rgb", "[" + std::to_string(report.rgb.r) + "," +
                                           std::to_string(report.rgb.g) + "," +
                                           std::to_string(report.rgb.b) + "]")
                       .add("background", report.background)
                       .str())
          .str();
  // Each ray of the report runs from its origin to its hit, or on out of
  // the scene.
  for (const auto& r : report.rays) {
    OverlaySegment seg;
    seg.from = r.origin;
    seg.kind = r.kind == RayKind::Reflected     ? OverlayKind::Reflected
               : r.kind == RayKind::Transmitted ? OverlayKind::Transmitted
               : r.kind == RayKind::Shadow      ? OverlayKind::Shadow
                                                : OverlayKind::Primary;
    seg.hit = r.hit;
    seg.to = r.hit ? r.point : r.origin + r.direction * kMissLength;
    out.segments.push_back(seg);
  }
  // Section 8.2: the ray through the screen point (x, y) has the direction
  // start + (x - 256) X + (y - 256) Y; image column c is x and row r is
  // scanline 511 - r, whose corner (c, 511 - r) lies at the picture point
  // (c, r + 1).
  const prime::cgl::Camera& cam = scene.camera;
  out.camera = {cam.eye,   cam.start - cam.xpath * 256.0 + cam.ypath * 255.0,
                cam.xpath, cam.ypath * -1.0,
                0.0,       1.0};
  out.column = static_cast<int>(std::floor(x));
  out.row = prime::cgl::Frame::kSize - 1 - static_cast<int>(std::floor(y));
  return out;
}

ProbeFactory addProbeOptions(CLI::App* cmd, const std::shared_ptr<ProbeFlags>& flags) {
  auto o = std::make_shared<CglOptions>();
  auto point = std::make_shared<std::vector<double>>();
  addCglOptions(cmd, *o);
  cmd->add_option("--point", *point,
                  "The package's own screen point X Y instead of --pixel: 0..512 from the "
                  "bottom-left, a pixel's integer corner (fractions reach the sub-pixel corners "
                  "of Figure 44)")
      ->expected(2)
      ->allow_extra_args(false)
      ->check(CLI::Range(0.0, 512.0));
  return [o, flags, point]() -> ProbeReport {
    double x = 0, y = 0;
    std::string where;
    if (flags->pixel.size() == 2 && point->empty()) {
      const int px = flags->pixel[0], py = flags->pixel[1];
      if (px < 0 || py < 0 || px >= prime::cgl::Frame::kSize || py >= prime::cgl::Frame::kSize)
        throw CLI::ValidationError("--pixel", "pixel " + std::to_string(px) + " " +
                                                  std::to_string(py) +
                                                  " is outside the picture (512 x 512)");
      // Row py from the top is scanline 511 - py; the pixel's ray goes
      // through its corner (x, scanline) (Figure 41).
      x = px;
      y = prime::cgl::Frame::kSize - 1 - py;
      where = "pixel " + std::to_string(px) + " " + std::to_string(py);
    } else if (point->size() == 2 && flags->pixel.empty()) {
      x = (*point)[0];
      y = (*point)[1];
      where = "screen point " + fmt(x) + " " + fmt(y);
    } else {
      throw CLI::ValidationError("probe", "give --pixel X Y or --point X Y");
    }
    const prime::cgl::SceneFile file = readCgl(*o, false);
    const prime::cgl::Scene scene = buildCgl(*o, file);
    const ProbedPixel probed = probePoint(scene, renderSettings(*o, file), o->file, where, x, y);
    ProbeReport out{probed.text, probed.json, ""};
    if (!flags->overlay.empty()) {
      // The frame trace writes, the tree over it.
      const prime::cgl::RenderResult picture = prime::cgl::render(scene, renderSettings(*o, file));
      const RgbImage frame = prime::cgl::toRgbImage(picture.frame);
      Image8 img;
      img.width = frame.width;
      img.height = frame.height;
      for (const Rgb& p : frame.pixels)
        for (int k = 0; k < 3; ++k)
          img.rgb.push_back(static_cast<std::uint8_t>(std::lround(p[k] * 255.0)));
      out.written = writeOverlay(flags->overlay, img, probed);
    }
    return out;
  };
}

}  // namespace prime::cli::cgl
